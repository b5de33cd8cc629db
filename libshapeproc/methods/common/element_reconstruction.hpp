// Output elements rebuilt from their samples (Ma et al. 2011, §3.1; the strategies compared in
// Landes et al. 2013, §7.2, Fig. 8). The EM moves each sample on its own, so an element's samples
// no longer sit exactly as its source's template; its shape is the source's, mapped by
// - rigid (the default): the rotation and translation that best map the template onto the samples
//   (Umeyama's least squares), so that every element keeps its drawn size;
// - similarity: the same with a uniform scale, the "rigid transform fitting" of Landes et al.
//   (rotation, translation and scaling);
// - tps: the similarity plus an interpolating thin-plate spline through every sample;
// - tps-approx: the same spline relaxed by a smoothing weight equal to the kernel's mean
//   magnitude over the template, half-way between the two.
// A single-sample element is its source's shape at the sample, turned by the orientation field.
// Splines need dimension + 1 samples; fewer fall back to the similarity.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/common/output_samples.hpp"

namespace shapeproc::methods {

enum class Reconstruction { rigid, similarity, tps, tps_approx };

// What a spline may do to an element: change its size (area, or volume) or its proportions (the
// ratio of its principal spreads) by at most this factor either way. The EM moves each sample on
// its own, and a spline through them follows every move: on a rigid exemplar, unbounded, it
// blows shapes up three or four times and stretches others into slivers. A spline beyond the
// bound is blended towards the element's rigid placement, by halves, until it is within it.
inline constexpr double kMaxSplineDistortion = 1.5;
const char* to_string(Reconstruction reconstruction);
Reconstruction parse_reconstruction(const std::string& text);  // throws core::ArgumentError

// x ↦ linear x + translation.
struct Similarity {
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
  Vec3 operator()(const Vec3& x) const { return linear * x + translation; }
};

// The least-squares similarity from `from` to `to` (same size, at least 1 point; 1 point: a
// translation); without `scaling`, a rigid motion.
Similarity fit_similarity(const std::vector<Vec3>& from, const std::vector<Vec3>& to, int dimension,
                          bool scaling = true);

// A thin-plate spline on top of a similarity: f(x) = S(x) + a + B x + Σ w_i U(|x − c_i|), with
// U(r) = r² log r in 2D and r in 3D, fitted so that f(c_i) = to_i (smoothing 0) or relaxed.
class ThinPlateSpline {
 public:
  ThinPlateSpline(const std::vector<Vec3>& from, const std::vector<Vec3>& to, int dimension,
                  bool interpolating);
  Vec3 operator()(const Vec3& x) const;

 private:
  double kernel(double r) const;
  int dimension_;
  Similarity base_;
  std::vector<Vec3> centres_;
  Eigen::MatrixXd weights_;  // (n + dimension + 1) x 3: the w_i, then a and the rows of B
};

// A copy of `shape` with every point mapped (2D: path end and control points; 3D: vertices).
geometry::Shape map_shape(const geometry::Shape& shape,
                          const std::function<Vec3(const Vec3&)>& map);

// The rigid motion that places element e's source shape (local coordinates) on its samples:
// Umeyama's fit without scale, or for a single sample, the sample's position and the orientation
// field's turn.
Similarity rigid_placement(const EmExemplar& exemplar, const OutputSamples& output, std::size_t e,
                           const geometry::Domain& domain, const OrientationField& orientation);

// The output scene: every element's shape rebuilt from its samples, window = the domain's box.
geometry::Scene reconstruct(const EmExemplar& exemplar, const OutputSamples& output,
                            const geometry::Domain& domain, const OrientationField& orientation,
                            Reconstruction rule);

}  // namespace shapeproc::methods
