#include "libshapeproc/fit/shape_classes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "libshapeproc/core/check.hpp"

namespace shapeproc::fit {

namespace {

// A shape's geometry in local coordinates: its structure (fill, closure, segment kinds, mesh
// triangles) as text and its coordinates in order. Shapes identical up to translation have the
// same structure and coordinates equal to a tolerance (compared, not rounded: rounding would
// part equal values that straddle a step).
struct Signature {
  std::string structure;
  std::vector<double> coordinates;

  explicit Signature(const geometry::Shape& shape) {
    if (const auto* planar = std::get_if<geometry::PlanarShape>(&shape.geometry)) {
      for (const geometry::Drawable2& d : planar->parts) {
        structure += d.filled() ? 'F' : 'S';
        for (const geometry::Path2& path : d.paths) {
          structure += path.closed ? 'C' : 'O';
          for (const geometry::Segment2& segment : path.segments) {
            structure += segment.cubic ? 'c' : 'l';
            add(segment.start);
            if (segment.cubic) {
              add(segment.control1);
              add(segment.control2);
            }
            add(segment.end);
          }
        }
      }
    } else if (const auto* mesh = std::get_if<geometry::MeshShape>(&shape.geometry)) {
      for (const geometry::Vec3& v : mesh->mesh.vertices) add(v);
      for (const auto& t : mesh->mesh.triangles)
        structure +=
            std::to_string(t[0]) + ',' + std::to_string(t[1]) + ',' + std::to_string(t[2]) + ';';
    } else {
      structure = "point";
    }
  }

  bool same(const Signature& other, double tolerance) const {
    if (structure != other.structure || coordinates.size() != other.coordinates.size())
      return false;
    for (std::size_t i = 0; i < coordinates.size(); ++i)
      if (std::abs(coordinates[i] - other.coordinates[i]) > tolerance) return false;
    return true;
  }

 private:
  template <class V>
  void add(const V& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) coordinates.push_back(v[i]);
  }
};

// Shapes identical up to translation, as used by one category's elements.
struct Identical {
  std::vector<int> shapes;
  int elements = 0;
  double area = 0.0, diagonal = 0.0;  // bounding box: area (volume in 3D) and diagonal
};

std::pair<double, double> size_of(const geometry::Shape& shape, int dimension) {
  const geometry::Box3 box = geometry::bounding_box(shape);
  if (box.isEmpty()) return {0.0, 0.0};
  return {geometry::measure(box, dimension), box.sizes().norm()};
}

bool smaller(const Identical& a, const Identical& b) {
  return std::tie(a.area, a.diagonal) < std::tie(b.area, b.diagonal);
}

// Cuts the size-ordered groups into at most `count` classes of about equal element counts, each
// of at least kMinElementsPerClass elements (a short last class joins the one before). A group
// starts a new class when more than half of its elements lie beyond the current class's share:
// rings' 5 dots, 11 small and 3 large rings (3 shares of 6.3 elements) make dots | rings; cutting
// only once the share was full put the small rings with the dots, and the short last class
// joined them too: one class for all, and the dots, cheap to place, took over the outputs.
std::vector<std::vector<const Identical*>> size_groups(std::vector<Identical>& groups, int count,
                                                       int elements) {
  std::sort(groups.begin(), groups.end(), smaller);
  std::vector<std::vector<const Identical*>> classes(1);
  std::vector<int> counts(1, 0);
  int cumulative = 0;
  for (const Identical& g : groups) {
    // The end of this class's share, against the middle of the group (both doubled, in integers).
    const int target = 2 * static_cast<int>(classes.size()) * elements / count;
    if (2 * cumulative + g.elements > target && counts.back() >= kMinElementsPerClass &&
        static_cast<int>(classes.size()) < count) {
      classes.emplace_back();
      counts.push_back(0);
    }
    classes.back().push_back(&g);
    counts.back() += g.elements;
    cumulative += g.elements;
  }
  if (classes.size() > 1 && counts.back() < kMinElementsPerClass) {
    classes[classes.size() - 2].insert(classes[classes.size() - 2].end(), classes.back().begin(),
                                       classes.back().end());
    classes.pop_back();
  }
  return classes;
}

}  // namespace

void assign_shape_classes(model::ShapeProcessModel& model, const geometry::Scene& exemplar) {
  model.shape_classes.clear();
  for (model::ModelShape& s : model.shapes) s.shape_class = -1;
  if (model.shapes.empty()) return;
  core::check(model.shapes.size() == exemplar.shapes.size(), "fit",
              "the model's shapes are not the exemplar's");
  const int dimension = exemplar.dimension;
  std::vector<int> uses(model.shapes.size(), 0);
  for (const geometry::Element& e : exemplar.elements) ++uses[static_cast<std::size_t>(e.shape)];

  // One tolerance for every shape (a scale-relative one would equate similar shapes).
  const double tolerance = kIdenticalTolerance * std::max(1.0, exemplar.window.sizes().norm());
  std::vector<model::ShapeClass> classes;
  std::vector<int> class_of(model.shapes.size(), -1);
  bool any_split = false;
  for (std::size_t c = 0; c < model.categories.size(); ++c) {
    const int category = static_cast<int>(c);
    // 1. Identical shapes: each shape joins the first group whose first shape it equals.
    std::vector<Identical> groups;
    std::vector<Signature> representatives;
    int elements = 0;
    for (std::size_t s = 0; s < model.shapes.size(); ++s) {
      if (model.shapes[s].category != category || uses[s] == 0) continue;
      const geometry::Shape& shape = model.shapes[s].shape;
      Signature signature(shape);
      std::size_t g = 0;
      while (g < groups.size() && !representatives[g].same(signature, tolerance)) ++g;
      if (g == groups.size()) {
        const auto [area, diagonal] = size_of(shape, dimension);
        groups.push_back({{}, 0, area, diagonal});
        representatives.push_back(std::move(signature));
      }
      groups[g].shapes.push_back(static_cast<int>(s));
      groups[g].elements += uses[s];
      elements += uses[s];
    }
    // 2. Too many for the elements: size groups.
    bool supported = true;
    for (const Identical& g : groups) supported = supported && g.elements >= kMinElementsPerClass;
    const int count = std::clamp(elements / kMinElementsPerClass, 1, kMaxSizeGroups);
    std::vector<std::vector<const Identical*>> cut;
    if (supported) {
      std::sort(groups.begin(), groups.end(), smaller);
      for (const Identical& g : groups) cut.push_back({&g});
    } else {
      cut = size_groups(groups, count, elements);
    }
    const int first = static_cast<int>(classes.size());
    for (std::size_t k = 0; k < cut.size(); ++k) {
      int in_class = 0;
      for (const Identical* g : cut[k]) {
        in_class += g->elements;
        for (int s : g->shapes) class_of[static_cast<std::size_t>(s)] = first + static_cast<int>(k);
      }
      const std::string label =
          supported ? "identical shapes"
                    : "size " + std::to_string(k + 1) + " of " + std::to_string(cut.size());
      classes.push_back({category, static_cast<double>(in_class) / elements, label});
    }
    any_split = any_split || cut.size() > 1;
    // Shapes no element uses: the class of the nearest bounding-box area.
    for (std::size_t s = 0; s < model.shapes.size(); ++s) {
      if (model.shapes[s].category != category || uses[s] > 0) continue;
      const double area = size_of(model.shapes[s].shape, dimension).first;
      int best = first;
      double best_gap = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < cut.size(); ++k) {
        for (const Identical* g : cut[k]) {
          if (std::abs(g->area - area) < best_gap) {
            best_gap = std::abs(g->area - area);
            best = first + static_cast<int>(k);
          }
        }
      }
      class_of[s] = best;
    }
  }
  // 3. One class everywhere: no classes.
  if (!any_split) return;
  model.shape_classes = std::move(classes);
  for (std::size_t s = 0; s < model.shapes.size(); ++s) model.shapes[s].shape_class = class_of[s];
}

}  // namespace shapeproc::fit
