#include "libshapeproc/model/shape_process_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::model {

namespace {

std::string number(double v) { return core::format_number(v); }

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw core::ArgumentError(where, what);
}

}  // namespace

const char* to_string(ParameterStatus status) {
  switch (status) {
    case ParameterStatus::free:
      return "free";
    case ParameterStatus::boundary:
      return "boundary";
    case ParameterStatus::unidentifiable:
      return "unidentifiable";
    case ParameterStatus::unbounded:
      return "unbounded";
    case ParameterStatus::unreachable:
      return "unreachable";
    case ParameterStatus::fixed:
      return "fixed";
  }
  return "fixed";
}

int ShapeProcessModel::layer_count() const {
  int last = 0;
  for (const CategoryParameters& c : categories) last = std::max(last, c.layer);
  return last + 1;
}

bool ShapeProcessModel::anchors(const PairInteraction& pair) const {
  return categories[static_cast<std::size_t>(pair.first)].anchor == pair.second ||
         categories[static_cast<std::size_t>(pair.second)].anchor == pair.first;
}

double ShapeProcessModel::interaction_range() const {
  double range = 0.0;
  for (const PairInteraction& pair : interactions)
    for (const AxisParameters& axis : pair.axes)
      if (!axis.thresholds.empty()) range = std::max(range, axis.thresholds.back());
  return range;
}

int ShapeProcessModel::interaction_index(int a, int b) const {
  if (a > b) std::swap(a, b);
  for (std::size_t p = 0; p < interactions.size(); ++p) {
    if (interactions[p].first == a && interactions[p].second == b) return static_cast<int>(p);
  }
  return -1;
}

geometry::MeasurementOptions ShapeProcessModel::measurement_options(bool periodic) const {
  geometry::MeasurementOptions options;
  options.distance = measurement.distance;
  options.direction = measurement.direction;
  options.directions = measurement.directions;
  options.proxy.tolerance = measurement.proxy_tolerance;
  options.periodic = periodic;
  return options;
}

geometry::Scene ShapeProcessModel::shape_space() const {
  geometry::Scene scene;
  scene.dimension = dimension;
  scene.units = units;
  for (const CategoryParameters& c : categories) scene.categories.push_back({c.name});
  if (shapes.empty()) {
    scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  } else {
    for (const ModelShape& s : shapes) scene.shapes.push_back(s.shape);
  }
  return scene;
}

namespace {

// One axis of a pair, at `at`: its canonical direction `expected`, thresholds and γ.
void validate_axis(const AxisParameters& axis, const std::string& at,
                   const geometry::Vec3& expected, int dimension) {
  if (!axis.direction.allFinite() || axis.direction.norm() == 0 ||
      (axis.direction.normalized() - expected).norm() > 1e-6 ||
      (dimension == 2 && axis.direction.z() != 0)) {
    std::ostringstream text;
    text << "expected the canonical direction (" << expected.x() << ", " << expected.y();
    if (dimension == 3) text << ", " << expected.z();
    text << ")";
    fail(at + ".direction", text.str());
  }
  if (axis.thresholds.empty())
    fail(at + ".thresholds", "at least the hard-core distance d0 is needed");
  for (std::size_t k = 0; k < axis.thresholds.size(); ++k) {
    const double d = axis.thresholds[k];
    if (!std::isfinite(d))
      fail(at + ".thresholds[" + std::to_string(k) + "]", "must be finite, got " + number(d));
    if (k > 0 && d < axis.thresholds[k - 1]) {
      fail(at + ".thresholds",
           "must not decrease, got " + number(d) + " after " + number(axis.thresholds[k - 1]));
    }
  }
  // A negative hard core lets the pair overlap (signed distances below 0 are overlap depths); its
  // bands, if it has any, must then reach beyond contact.
  if (axis.thresholds.front() < 0 && axis.thresholds.size() > 1 && !(axis.thresholds.back() > 0)) {
    fail(at + ".thresholds", "a pair that may overlap (d0 " + number(axis.thresholds.front()) +
                                 " < 0) needs a last threshold above 0, got " +
                                 number(axis.thresholds.back()));
  }
  if (axis.gammas.size() + 1 != axis.thresholds.size()) {
    fail(at + ".gammas", "expected " + std::to_string(axis.thresholds.size() - 1) +
                             " values (one per band), got " + std::to_string(axis.gammas.size()));
  }
  for (std::size_t k = 0; k < axis.gammas.size(); ++k) {
    const double g = axis.gammas[k];
    if (!(std::isfinite(g) && g >= 0))
      fail(at + ".gammas[" + std::to_string(k) + "]", "must be finite and >= 0, got " + number(g));
  }
  if (!axis.saturations.empty() && axis.saturations.size() != axis.gammas.size()) {
    fail(at + ".saturations", "expected " + std::to_string(axis.gammas.size()) +
                                  " values (one per band), got " +
                                  std::to_string(axis.saturations.size()));
  }
  for (std::size_t k = 0; k < axis.saturations.size(); ++k)
    if (axis.saturations[k] < 0)
      fail(at + ".saturations[" + std::to_string(k) + "]",
           "must be >= 0 (0: a pairwise band), got " + std::to_string(axis.saturations[k]));
}

// A saturated band counts each element's neighbours of the other category, which it sees only
// when both lie in one layer.
void validate_saturation(const ShapeProcessModel& model, const PairInteraction& pair,
                         const std::string& where) {
  bool saturated = false;
  for (const AxisParameters& axis : pair.axes)
    for (int s : axis.saturations) saturated = saturated || s > 0;
  const auto layer = [&](int c) { return model.categories[static_cast<std::size_t>(c)].layer; };
  if (saturated && layer(pair.first) != layer(pair.second))
    fail(where + ".axes", "a saturated band needs both categories in one layer, got layers " +
                              std::to_string(layer(pair.first)) + " and " +
                              std::to_string(layer(pair.second)));
}

// The pairs' interactions: category indices, each pair once, the axes the directions give.
void validate_interactions(const ShapeProcessModel& model, const geometry::DirectionBins& bins) {
  const int categories = static_cast<int>(model.categories.size());
  std::vector<bool> seen(
      static_cast<std::size_t>(categories) * static_cast<std::size_t>(categories), false);
  for (std::size_t p = 0; p < model.interactions.size(); ++p) {
    const PairInteraction& pair = model.interactions[p];
    const std::string where = "interaction[" + std::to_string(p) + "]";
    if (pair.first < 0 || pair.second < 0 || pair.first >= categories ||
        pair.second >= categories) {
      fail(where + ".categories",
           "category indices must be in 0.." + std::to_string(categories - 1) + ", got [" +
               std::to_string(pair.first) + ", " + std::to_string(pair.second) + "]");
    }
    const int a = std::min(pair.first, pair.second), b = std::max(pair.first, pair.second);
    const std::size_t slot = static_cast<std::size_t>(a) * static_cast<std::size_t>(categories) +
                             static_cast<std::size_t>(b);
    if (seen[slot]) fail(where + ".categories", "this pair of categories is listed twice");
    seen[slot] = true;
    if (static_cast<int>(pair.axes.size()) != bins.axis_count() && pair.axes.size() != 1) {
      fail(where + ".axes", "expected 1 (isotropic) or " + std::to_string(bins.axis_count()) +
                                " axes for " + std::to_string(model.measurement.directions) +
                                " directions in " + std::to_string(model.dimension) + "D, got " +
                                std::to_string(pair.axes.size()));
    }
    for (std::size_t i = 0; i < pair.axes.size(); ++i) {
      validate_axis(pair.axes[i], where + ".axes[" + std::to_string(i) + "]",
                    bins.axis_direction(static_cast<int>(i)), model.dimension);
    }
    validate_saturation(model, pair, where);
  }
}

// The shapes, their categories and classes, and the shape classes.
void validate_shapes(const ShapeProcessModel& model) {
  const int categories = static_cast<int>(model.categories.size());
  for (std::size_t s = 0; s < model.shapes.size(); ++s) {
    const ModelShape& shape = model.shapes[s];
    const std::string where = "shapes[" + std::to_string(s) + "]";
    if (shape.category < 0 || shape.category >= categories)
      fail(where + ".category", "out of range");
    const int classes = static_cast<int>(model.shape_classes.size());
    if (classes == 0 && shape.shape_class != -1)
      fail(where + ".class", "names a class but the model has no shape classes");
    if (classes > 0) {
      if (shape.shape_class < 0 || shape.shape_class >= classes)
        fail(where + ".class", "out of range");
      else if (model.shape_classes[static_cast<std::size_t>(shape.shape_class)].category !=
               shape.category)
        fail(where + ".class", "belongs to another category");
    }
    const int d = geometry::dimension(shape.shape);
    if (d != 0 && d != model.dimension)
      fail(where, "a " + std::to_string(d) + "D shape in a " + std::to_string(model.dimension) +
                      "D model");
  }
  if (!model.shape_classes.empty() && model.shapes.empty())
    fail("shape_classes", "a point model has no shape classes");
  for (std::size_t k = 0; k < model.shape_classes.size(); ++k) {
    const ShapeClass& c = model.shape_classes[k];
    const std::string where = "shape_classes[" + std::to_string(k) + "]";
    if (c.category < 0 || c.category >= categories) fail(where + ".category", "out of range");
    if (!(std::isfinite(c.weight) && c.weight > 0))
      fail(where + ".weight", "must be finite and > 0, got " + number(c.weight));
    bool any = false;
    for (const ModelShape& s : model.shapes) any = any || s.shape_class == static_cast<int>(k);
    if (!any) fail(where, "holds no shape");
  }
  if (!model.shapes.empty()) {
    for (int c = 0; c < categories; ++c) {
      bool any = false;
      for (const ModelShape& s : model.shapes) any = any || s.category == c;
      if (!any)
        fail("shapes",
             "category " + std::to_string(c) + " (" + model.categories[c].name + ") has no shape");
    }
  }
}

}  // namespace

// The neighbour offsets: kinds in range, finite offsets in the model's dimension, positive
// weights and radii.
void validate_neighbour_offsets(const ShapeProcessModel& model) {
  const NeighbourOffsets& n = model.neighbour_offsets;
  if (n.empty()) return;
  const int kinds =
      static_cast<int>(model.shapes.empty() ? model.categories.size() : model.shapes.size());
  if (n.radii.empty()) fail("neighbour_offsets.radii", "at least one radius is needed");
  if (!(n.share >= 0 && n.share < 1))
    fail("neighbour_offsets.share", "must be in [0, 1), got " + number(n.share));
  for (std::size_t r = 0; r < n.radii.size(); ++r)
    if (!(std::isfinite(n.radii[r]) && n.radii[r] > 0))
      fail("neighbour_offsets.radii[" + std::to_string(r) + "]",
           "must be finite and > 0, got " + number(n.radii[r]));
  for (std::size_t k = 0; k < n.offsets.size(); ++k) {
    const NeighbourOffset& o = n.offsets[k];
    const std::string where = "neighbour_offsets.offsets[" + std::to_string(k) + "]";
    if (o.from < 0 || o.to < 0 || o.from >= kinds || o.to >= kinds)
      fail(where, std::string("names a ") + (model.shapes.empty() ? "category" : "shape") +
                      " out of range");
    if (!o.offset.allFinite() || (model.dimension == 2 && o.offset.z() != 0))
      fail(where + ".offset", "must be finite (and 0 along z in 2D)");
    if (!(std::isfinite(o.weight) && o.weight > 0))
      fail(where + ".weight", "must be finite and > 0, got " + number(o.weight));
  }
}

void validate(const ShapeProcessModel& model) {
  if (model.dimension != 2 && model.dimension != 3)
    fail("dimension", "must be 2 or 3, got " + std::to_string(model.dimension));
  if (model.categories.empty()) fail("categories", "at least one category is needed");
  for (std::size_t c = 0; c < model.categories.size(); ++c) {
    const double beta = model.categories[c].beta;
    if (!(std::isfinite(beta) && beta > 0)) {
      fail("categories[" + std::to_string(c) + "].beta",
           "must be finite and > 0, got " + number(beta));
    }
    const int layer = model.categories[c].layer;
    if (layer < 0 || layer >= static_cast<int>(model.categories.size()))
      fail("categories[" + std::to_string(c) + "].layer",
           "must be at least 0 and below the number of categories, got " + std::to_string(layer));
    const int anchor = model.categories[c].anchor;
    if (anchor >= 0 && (anchor >= static_cast<int>(model.categories.size()) ||
                        model.categories[static_cast<std::size_t>(anchor)].layer >= layer ||
                        model.interaction_index(static_cast<int>(c), anchor) < 0))
      fail("categories[" + std::to_string(c) + "].anchor",
           "must be -1 or a category of a lower layer that this one interacts with, got " +
               std::to_string(anchor));
    if (!std::isfinite(model.categories[c].anchor_reach))
      fail("categories[" + std::to_string(c) + "].anchor_reach", "must be finite");
  }
  const geometry::DirectionBins bins = [&] {
    try {
      return geometry::DirectionBins(model.dimension, model.measurement.directions);
    } catch (const std::invalid_argument& e) {
      fail("measurement.directions", e.what());
    }
  }();
  // The pair tables hold categories² entries: a file of 65,537 categories had wrapped an int.
  if (model.categories.size() > kMaxCategories) {
    fail("categories", "at most " + std::to_string(kMaxCategories) + " categories, got " +
                           std::to_string(model.categories.size()));
  }
  validate_interactions(model, bins);
  validate_shapes(model);
  validate_neighbour_offsets(model);
}

std::vector<std::string> statistic_names(const ShapeProcessModel& model) {
  std::vector<std::string> names;
  for (const CategoryParameters& c : model.categories) names.push_back("elements " + c.name);
  for (std::size_t p = 0; p < model.interactions.size(); ++p) {
    const PairInteraction& pair = model.interactions[p];
    for (std::size_t i = 0; i < pair.axes.size(); ++i)
      for (std::size_t k = 0; k < pair.axes[i].gammas.size(); ++k)
        names.push_back("pairs " + std::to_string(p) + ", axis " + std::to_string(i) + ", band " +
                        std::to_string(k + 1));
  }
  for (std::size_t k = 0; k < model.shape_classes.size(); ++k)
    names.push_back("class " + std::to_string(k) + " (" + model.shape_classes[k].label + ")");
  return names;
}

}  // namespace shapeproc::model
