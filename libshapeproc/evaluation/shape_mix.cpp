#include "libshapeproc/evaluation/shape_mix.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "libshapeproc/evaluation/fidelity.hpp"
#include "libshapeproc/fit/fit_thresholds.hpp"
#include "libshapeproc/fit/shape_classes.hpp"
#include "libshapeproc/geometry/shape_size.hpp"

namespace shapeproc::evaluation {

namespace {

// Sizes closer than this (in summed log ratios: about 1%) are one size.
constexpr double kSameSize = 0.01;

// Classes whose elements cannot be told apart by size (a stroke and its turned copy, identical
// shapes of two classes) are one kind here: an output element could not say which it is.
void merge_classes_of_one_size(const geometry::Scene& exemplar,
                               const std::vector<geometry::ShapeSize>& sizes,
                               std::vector<std::string>& classes, std::vector<int>& element_class) {
  std::vector<int> parent(classes.size());
  for (std::size_t c = 0; c < parent.size(); ++c) parent[c] = static_cast<int>(c);
  const auto root = [&](int c) {
    while (parent[static_cast<std::size_t>(c)] != c) c = parent[static_cast<std::size_t>(c)];
    return c;
  };
  const auto& elements = exemplar.elements;
  for (std::size_t i = 0; i < elements.size(); ++i)
    for (std::size_t j = i + 1; j < elements.size(); ++j) {
      if (elements[i].category != elements[j].category) continue;
      const int a = root(element_class[i]), b = root(element_class[j]);
      if (a == b) continue;
      if (geometry::size_distance(sizes[static_cast<std::size_t>(elements[i].shape)],
                                  sizes[static_cast<std::size_t>(elements[j].shape)]) < kSameSize)
        parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  std::vector<int> renumbered(classes.size(), -1);
  std::vector<std::string> merged;
  for (std::size_t c = 0; c < classes.size(); ++c) {
    const int r = root(static_cast<int>(c));
    if (renumbered[static_cast<std::size_t>(r)] < 0) {
      renumbered[static_cast<std::size_t>(r)] = static_cast<int>(merged.size());
      merged.push_back(classes[static_cast<std::size_t>(r)]);
    } else if (r != static_cast<int>(c)) {
      merged[static_cast<std::size_t>(renumbered[static_cast<std::size_t>(r)])] +=
          " + " + classes[c];
    }
  }
  for (int& c : element_class) c = renumbered[static_cast<std::size_t>(root(c))];
  classes = std::move(merged);
}

}  // namespace

ShapeKinds shape_kinds(const geometry::Scene& exemplar) {
  model::ShapeProcessModel skeleton = fit::model_skeleton(exemplar, fit::FitOptions{});
  fit::assign_shape_classes(skeleton, exemplar);
  // Classes: the exemplar's shape classes, or one per category where it has none.
  ShapeKinds mix;
  std::vector<int> class_of_shape(exemplar.shapes.size(), -1);
  std::vector<int> category_class(exemplar.categories.size(), -1);
  if (!skeleton.shape_classes.empty()) {
    for (const model::ShapeClass& c : skeleton.shape_classes)
      mix.classes.push_back(exemplar.categories[static_cast<std::size_t>(c.category)].name +
                            (c.label.empty() ? "" : ": " + c.label));
    for (std::size_t s = 0; s < exemplar.shapes.size() && s < skeleton.shapes.size(); ++s)
      class_of_shape[s] = skeleton.shapes[s].shape_class;
  }
  std::vector<int> element_class;
  for (const geometry::Element& e : exemplar.elements) {
    int c = class_of_shape[static_cast<std::size_t>(e.shape)];
    if (c < 0) {  // a category of one class
      int& own = category_class[static_cast<std::size_t>(e.category)];
      if (own < 0) {
        own = static_cast<int>(mix.classes.size());
        mix.classes.push_back(exemplar.categories[static_cast<std::size_t>(e.category)].name);
      }
      c = own;
    }
    element_class.push_back(c);
  }
  // Each exemplar shape's size, once; output shapes measured once each.
  std::vector<geometry::ShapeSize> exemplar_size;
  for (const geometry::Shape& s : exemplar.shapes) exemplar_size.push_back(geometry::shape_size(s));
  merge_classes_of_one_size(exemplar, exemplar_size, mix.classes, element_class);
  mix.exemplar.assign(mix.classes.size(), 0);
  for (const int c : element_class) ++mix.exemplar[static_cast<std::size_t>(c)];
  mix.elements = static_cast<int>(exemplar.elements.size());

  // The exemplar's kinds of element, each (category, shape) once in the order met: every element
  // of a kind has the kind's class.
  std::vector<std::pair<int, int>> seen;
  for (std::size_t i = 0; i < exemplar.elements.size(); ++i) {
    const geometry::Element& e = exemplar.elements[i];
    if (std::find(seen.begin(), seen.end(), std::make_pair(e.category, e.shape)) != seen.end())
      continue;
    seen.emplace_back(e.category, e.shape);
    mix.kinds.push_back({exemplar.categories[static_cast<std::size_t>(e.category)].name,
                         exemplar_size[static_cast<std::size_t>(e.shape)], element_class[i]});
  }
  return mix;
}

ShapeMix shape_mix(const ShapeKinds& exemplar, const geometry::Scene& output) {
  ShapeMix mix;
  mix.classes = exemplar.classes;
  mix.exemplar = exemplar.exemplar;
  mix.output.assign(mix.classes.size(), 0);
  std::vector<geometry::ShapeSize> output_size;
  for (const geometry::Shape& s : output.shapes) output_size.push_back(geometry::shape_size(s));
  for (const geometry::Element& o : output.elements) {
    const std::string& name = output.categories[static_cast<std::size_t>(o.category)].name;
    double best = std::numeric_limits<double>::infinity();
    int chosen = -1;
    for (const ShapeKinds::Kind& k : exemplar.kinds) {
      if (k.category != name) continue;
      const double d =
          geometry::size_distance(output_size[static_cast<std::size_t>(o.shape)], k.size);
      if (d < best) {
        best = d;
        chosen = k.shape_class;
      }
    }
    if (chosen < 0)
      ++mix.unmatched;
    else
      ++mix.output[static_cast<std::size_t>(chosen)];
  }

  // Pearson's chi-square of the output's counts against the exemplar's shares.
  int total = 0;
  for (const int n : mix.output) total += n;
  const double exemplar_total = static_cast<double>(exemplar.elements);
  if (mix.classes.size() < 2 || total == 0) return mix;
  for (std::size_t c = 0; c < mix.classes.size(); ++c) {
    const double expected = total * mix.exemplar[c] / exemplar_total;
    const double gap = mix.output[c] - expected;
    mix.chi_square += gap * gap / expected;
  }
  mix.degrees = static_cast<int>(mix.classes.size()) - 1;
  mix.p_value = chi_square_upper_tail(mix.chi_square, mix.degrees);
  return mix;
}

ShapeMix shape_mix(const geometry::Scene& exemplar, const geometry::Scene& output) {
  return shape_mix(shape_kinds(exemplar), output);
}

}  // namespace shapeproc::evaluation
