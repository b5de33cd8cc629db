// The shape-process model (paper §5; docs/mathematics.md, "The density"):
//   f(x) ∝ ∏_n β_{c_n} ∏_{n<m} Γ(x_n, x_m),
// with, for the categories (c, c') of a pair and the axis bin i of its relative orientation,
//   Γ = 0 if d < δ_{i,0} (hard core), γ_{i,k} if δ_{i,k−1} ≤ d < δ_{i,k} (k = 1..K), 1 if d ≥
//   δ_{i,K}.
// This file holds the parameters as a user edits them; interaction.hpp compiles them for
// evaluation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/shape.hpp"
#include "libshapeproc/model/fit_record.hpp"

namespace shapeproc::model {

// How a parameter came out of the fit (free parameters are estimated normally).
enum class ParameterStatus {
  free,
  boundary,        // no observed pair in the band: γ = 0 is the maximum (on the boundary)
  unidentifiable,  // neither observed pairs nor quadrature exposure: γ = 1 by convention
  unbounded,       // the pseudo-likelihood grows without limit (the exemplar separates the
                   // statistics); the estimate sits at the search bound |log γ| = 30
  fixed,           // set by hand (a loaded model without fit information)
  unreachable,     // maximum likelihood: the chains never vary the statistic however far the
                   // parameter is pushed (a jammed exemplar); left at its start value
};

// The most categories a model may have: its pair tables hold categories² entries.
constexpr std::size_t kMaxCategories = 4096;

struct CategoryParameters {
  std::string name;
  double beta = 1.0;  // intensity per unit area (volume in 3D), in exemplar units
  double beta_standard_error = std::numeric_limits<double>::quiet_NaN();
  // free when fitted normally; unbounded when it follows the data points' share (no finite
  // maximum); fixed when set by hand.
  ParameterStatus beta_status = ParameterStatus::fixed;
  // The stage at which the category's elements are placed (docs/fit.md, "Layers"): layer 0
  // first, then each later layer given the elements of the earlier ones, which do not see it.
  // Decorations on base shapes, or mushrooms in trees, lie one layer above their bases.
  int layer = 0;
  // The category (its base, in a lower layer) that every element of this one must lie closer
  // than `anchor_reach` to (shape distance: at 0, overlap or lie inside one of its elements): its
  // intensity is 0 elsewhere. -1: none.
  int anchor = -1;
  double anchor_reach = 0.0;
  // A category the model places but an output does not draw: the centres of a clustered
  // pattern's clusters, which its visible categories are anchored to (docs/fit.md, "Clusters").
  bool hidden = false;
};

struct AxisParameters {
  geometry::Vec3 direction = geometry::Vec3::UnitX();  // representative canonical direction
  // δ_0 ≤ δ_1 ≤ … ≤ δ_K on the signed shape distance: below 0 it is minus the depth of an
  // overlap (geometry/overlap_depth.hpp), so δ_0 < 0 lets the pair overlap or nest that deep.
  std::vector<double> thresholds;
  std::vector<double> gammas;                 // γ_1 … γ_K (≥ 0)
  std::vector<double> gamma_standard_errors;  // NaN where not estimated
  std::vector<ParameterStatus> status;        // per band
  std::vector<int> observed_pairs;            // exemplar pairs per band (fit only)
  // Per band, the saturation s of a Geyer term (docs/mathematics.md, "Saturation"); empty, or 0
  // for a band, is a pairwise band. A saturated band counts, for each element of the pair's
  // categories, at most s of its neighbours in the band: its factor in the density is
  // γ^{Σ_i min(s, t_i(x))}, so that an attraction clusters without condensing.
  std::vector<int> saturations;
  int saturation(std::size_t band) const {
    return band < saturations.size() ? saturations[band] : 0;
  }
};

// The interaction of one unordered pair of categories: one entry per axis bin, or a single one
// that holds for every direction (an isotropic pair: the fit pools the axes of a pair whose
// exemplar pairs are too few to fit each, fit/parameter_budget.hpp).
struct PairInteraction {
  int first = 0, second = 0;  // category indices, first ≤ second
  std::vector<AxisParameters> axes;
  // Why the fit gave the pair these axes and bands ("isotropic, 1 band: 10 elements of 'tree'");
  // empty for a pair fitted with every axis and band, or written by hand.
  std::string choice;
  bool isotropic() const { return axes.size() == 1; }
};

struct MeasurementSettings {
  geometry::DistanceKind distance = geometry::DistanceKind::shape;
  geometry::DirectionKind direction = geometry::DirectionKind::gravitation;
  int directions = 8;  // 2D: even or 1; 3D: 12 or 1
  double proxy_tolerance = geometry::ProxyOptions{}.tolerance;
};

struct ModelShape {
  geometry::Shape shape;  // local coordinates, bounding-box centre at the origin
  int category = 0;
  int shape_class = -1;  // index into ShapeProcessModel::shape_classes; -1 when there are none
};

// Shapes of one category that the model counts together: shapes identical up to translation, or
// a group of them by size (fit/shape_classes.hpp). A class's intensity is β_c w, shared equally
// by its shapes, so that the class counts are sufficient statistics and samples keep the
// exemplar's mix of shapes. Fitted models have weights summing to 1 over a category's classes,
// so that β_c stays the category's intensity (and `edit --beta` scales every class of it).
struct ShapeClass {
  int category = 0;
  double weight = 1.0;  // > 0; the class's share of β_c
  std::string label;    // how the class was formed ("identical", "size 2 of 4"), may be empty
};

// Where the sampler proposes births besides uniformly (sample/neighbour_births.hpp;
// docs/mathematics.md, "Births near neighbours"): an element of kind `from` had a neighbour of kind
// `to` at `offset` (its reference position minus the element's) in the exemplar, with this share of
// the kind's offsets. A kind is a shape index, or a category index for a point pattern. The offsets
// steer proposals only: the density, and so every sample's distribution, does not depend on them.
struct NeighbourOffset {
  int from = 0, to = 0;
  geometry::Vec3 offset = geometry::Vec3::Zero();
  double weight = 1.0;  // > 0
};

struct NeighbourOffsets {
  std::vector<NeighbourOffset> offsets;
  // A proposal lands uniformly in a ball around the offset, of one of these radii (each as
  // likely): a small one that hits a tight packing's slot, a larger one that explores.
  std::vector<double> radii;
  // The share of birth proposals drawn near a neighbour, in [0, 1): the fit's chains used it, and
  // every chain of the model uses it unless told otherwise (sample::SamplerOptions). 0: births
  // are uniform only, the offsets merely recorded.
  double share = 0.0;
  bool empty() const { return offsets.empty(); }
};

struct ShapeProcessModel {
  int dimension = 2;
  std::string units = "px";
  MeasurementSettings measurement;
  std::vector<CategoryParameters> categories;
  std::vector<PairInteraction> interactions;  // pairs not listed do not interact (Γ = 1)
  std::vector<ModelShape> shapes;             // empty for point patterns
  // Empty: every shape of a category is equally likely (one class per category). Otherwise every
  // shape names its class.
  std::vector<ShapeClass> shape_classes;
  NeighbourOffsets neighbour_offsets;  // empty: births are proposed uniformly only
  std::optional<FitRecord> fit;        // how the model was fitted; none for a model written by hand

  // Largest δ_K over every pair and axis: beyond it no pair interacts.
  double interaction_range() const;
  // The number of layers: one more than the largest category layer (1 for an unlayered model).
  int layer_count() const;
  // Whether one category of `pair` is anchored to the other: its bands then say where on its
  // base the anchored category lies, not how the two attract or repel.
  bool anchors(const PairInteraction& pair) const;
  // Index into `interactions` of the pair (a, b) in either order, or -1.
  int interaction_index(int a, int b) const;
  // Measurement options for a PairMeasurer on this model's shapes.
  geometry::MeasurementOptions measurement_options(bool periodic) const;
  // The shape space as a scene (window and elements empty), for a PairMeasurer.
  geometry::Scene shape_space() const;
};

// Checks every invariant (β > 0 finite, layers from 0 to below the number of categories, thresholds
// finite and not decreasing, a last one above 0 where the first is below (a pair that may overlap),
// one γ per band, γ ≥ 0 finite, categories in range and each pair once, axes matching the canonical
// directions of `measurement.directions` (or one, isotropic), shape categories in range, shape
// dimensions matching). Throws std::invalid_argument with the path of the offending field
// ("interaction[1].axes[2].gammas[0]: must be finite and >= 0, got -1").
void validate(const ShapeProcessModel& model);

const char* to_string(ParameterStatus status);

// Names of the sufficient statistics t(x) in θ order (model/interaction.hpp): "elements NAME" per
// category, "pairs P, axis I, band K" per band (pairs in the model's order), "class K (LABEL)" per
// shape class.
std::vector<std::string> statistic_names(const ShapeProcessModel& model);

}  // namespace shapeproc::model
