#include "libshapeproc/fit/shape_classes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "libshapeproc/core/check.hpp"

namespace shapeproc::fit {

namespace {

// A shape's geometry in local coordinates, each number rounded to `quantum`: equal keys for
// shapes identical up to translation.
class ShapeKey {
 public:
  explicit ShapeKey(double quantum) : quantum_(quantum) {}

  std::string of(const geometry::Shape& shape) {
    key_.clear();
    if (const auto* planar = std::get_if<geometry::PlanarShape>(&shape.geometry)) {
      for (const geometry::Drawable2& d : planar->parts) {
        key_ += d.filled() ? 'F' : 'S';
        for (const geometry::Path2& path : d.paths) {
          key_ += path.closed ? 'C' : 'O';
          for (const geometry::Segment2& s : path.segments) {
            add(s.start);
            if (s.cubic) {
              add(s.control1);
              add(s.control2);
            }
            add(s.end);
          }
        }
      }
    } else if (const auto* mesh = std::get_if<geometry::MeshShape>(&shape.geometry)) {
      for (const geometry::Vec3& v : mesh->mesh.vertices) add(v);
      for (const auto& t : mesh->mesh.triangles)
        key_ += std::to_string(t[0]) + ',' + std::to_string(t[1]) + ',' + std::to_string(t[2]);
    } else {
      key_ = "point";
    }
    return key_;
  }

 private:
  template <class V>
  void add(const V& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i)
      key_ += std::to_string(std::llround(v[i] / quantum_)) + ',';
    key_ += ';';
  }

  double quantum_;
  std::string key_;
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
  const geometry::Vec3 sizes = box.sizes();
  return {sizes.head(dimension).prod(), sizes.norm()};
}

bool smaller(const Identical& a, const Identical& b) {
  return std::tie(a.area, a.diagonal) < std::tie(b.area, b.diagonal);
}

// Cuts the size-ordered groups into at most `count` classes of about equal element counts, each
// of at least kMinElementsPerClass elements (a short last class joins the one before).
std::vector<std::vector<const Identical*>> size_groups(std::vector<Identical>& groups, int count,
                                                       int elements) {
  std::sort(groups.begin(), groups.end(), smaller);
  std::vector<std::vector<const Identical*>> classes(1);
  std::vector<int> counts(1, 0);
  int cumulative = 0;
  for (const Identical& g : groups) {
    const int target = static_cast<int>(classes.size()) * elements / count;  // end of this class
    if (cumulative >= target && counts.back() >= kMinElementsPerClass &&
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

  // One quantum for every shape (a scale-relative one would equate similar shapes).
  ShapeKey key(1e-6 * std::max(1.0, exemplar.window.sizes().norm()));
  std::vector<model::ShapeClass> classes;
  std::vector<int> class_of(model.shapes.size(), -1);
  bool any_split = false;
  for (std::size_t c = 0; c < model.categories.size(); ++c) {
    const int category = static_cast<int>(c);
    // 1. Identical shapes.
    std::map<std::string, Identical> by_key;
    int elements = 0;
    for (std::size_t s = 0; s < model.shapes.size(); ++s) {
      if (model.shapes[s].category != category || uses[s] == 0) continue;
      const geometry::Shape& shape = model.shapes[s].shape;
      const auto [area, diagonal] = size_of(shape, dimension);
      Identical& g = by_key[key.of(shape)];
      g.shapes.push_back(static_cast<int>(s));
      g.elements += uses[s];
      g.area = area;
      g.diagonal = diagonal;
      elements += uses[s];
    }
    std::vector<Identical> groups;
    for (auto& entry : by_key) groups.push_back(std::move(entry.second));
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
