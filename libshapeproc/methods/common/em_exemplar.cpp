#include "libshapeproc/methods/common/em_exemplar.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/fit/fit_thresholds.hpp"
#include "libshapeproc/fit/shape_classes.hpp"
#include "libshapeproc/geometry/nearest_neighbours.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"

namespace shapeproc::methods {

bool EmExemplar::same_place(int a, int b) const {
  if (a == b) return true;
  if (tile_period.isZero()) return false;
  const std::size_t i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  const geometry::Element& x = scene.elements[static_cast<std::size_t>(samples.element[i])];
  const geometry::Element& y = scene.elements[static_cast<std::size_t>(samples.element[j])];
  if (x.shape != y.shape || samples.sample_id[i] != samples.sample_id[j]) return false;
  Vec3 d = samples.positions[i] - samples.positions[j];
  for (int axis = 0; axis < 3; ++axis)
    if (tile_period[axis] > 0)
      d[axis] -= tile_period[axis] * std::round(d[axis] / tile_period[axis]);
  return d.norm() <= 1e-6 * std::max(1.0, spacing);
}

double EmExemplar::attribute_distance(int element_a, int element_b) const {
  const auto a = static_cast<std::size_t>(element_a), b = static_cast<std::size_t>(element_b);
  return (category[a] != category[b] ? 1.0 : 0.0) + (shape_class[a] != shape_class[b] ? 1.0 : 0.0);
}

const std::vector<int>& EmExemplar::samples_with_key(int key) const {
  static const std::vector<int> none;
  return key >= 0 && key < static_cast<int>(by_key.size()) ? by_key[static_cast<std::size_t>(key)]
                                                           : none;
}

double mean_nearest_distance(const std::vector<geometry::Element>& elements,
                             const geometry::Domain& domain) {
  if (elements.size() < 2) return 0.0;
  std::vector<Vec3> positions;
  for (const geometry::Element& e : elements) positions.push_back(e.position);
  double sum = 0.0;
  for (const auto& nearest : geometry::nearest_offsets(positions, domain, 1))
    sum += nearest.front().norm();
  return sum / static_cast<double>(elements.size());
}

ElementClasses classify_elements(const geometry::Scene& scene) {
  model::ShapeProcessModel skeleton = fit::model_skeleton(scene, fit::FitOptions{});
  fit::assign_shape_classes(skeleton, scene);
  const int classes = std::max<int>(1, static_cast<int>(skeleton.shape_classes.size()) + 1);
  ElementClasses out;
  for (const geometry::Element& e : scene.elements) {
    const int shape_class = skeleton.shapes.empty()
                                ? -1
                                : skeleton.shapes[static_cast<std::size_t>(e.shape)].shape_class;
    out.category.push_back(e.category);
    out.shape_class.push_back(shape_class);
    out.attribute.push_back(e.category * classes + shape_class + 1);
  }
  return out;
}

EmExemplar analyse_exemplar(const geometry::Scene& scene, geometry::Boundary boundary, double rings,
                            const SampleOptions& options) {
  if (scene.elements.size() < 2)
    throw core::ArgumentError("neighbourhood EM", "the exemplar needs at least 2 elements");
  if (!(rings > 0)) throw core::ArgumentError("neighbourhood EM", "rings must be > 0");
  EmExemplar ex;
  ex.scene = scene;
  ex.boundary = boundary;
  // A tile smaller than its wide neighbourhoods' diameter is repeated until it holds them: on its
  // own torus the nearest image would miss the elements' further images.
  if (boundary == geometry::Boundary::torus) {
    ex.tile_period = scene.window.sizes();
    if (scene.dimension == 2) ex.tile_period.z() = 0.0;
    const geometry::Domain tile(scene.window, scene.dimension, boundary);
    ex.scene = geometry::repeat_to_reach(
        scene, 4.0 * (rings + 0.5) * mean_nearest_distance(scene.elements, tile));
  }
  const geometry::Domain domain(ex.scene.window, ex.scene.dimension, boundary);
  ex.templates = sample_templates(ex.scene, options);
  ex.samples = place_samples(ex.scene, ex.templates);
  ElementClasses classes = classify_elements(ex.scene);
  ex.category = std::move(classes.category);
  ex.shape_class = std::move(classes.shape_class);
  ex.attribute = std::move(classes.attribute);
  for (std::size_t s = 0; s < ex.samples.size(); ++s)
    ex.sample_attribute.push_back(ex.attribute[static_cast<std::size_t>(ex.samples.element[s])]);
  ex.spacing = mean_nearest_distance(ex.scene.elements, domain);
  ex.radius = (rings + 0.5) * ex.spacing;
  ex.density = static_cast<double>(ex.scene.elements.size()) / domain.measure();

  // Positions wrapped into the window on a torus, so that the grid holds them.
  std::vector<Vec3> positions = ex.samples.positions;
  for (Vec3& p : positions) p = domain.wrap(p);
  const geometry::NeighbourhoodIndex near_index(positions, ex.samples.key, ex.sample_attribute,
                                                domain, ex.radius);
  const geometry::NeighbourhoodIndex wide_index(positions, ex.samples.key, ex.sample_attribute,
                                                domain, 2.0 * ex.radius);
  // Sorted by key, so that the pairing visits only each key's range.
  const auto by_key = [](const geometry::Neighbour& a, const geometry::Neighbour& b) {
    return a.key < b.key || (a.key == b.key && a.element < b.element);
  };
  for (std::size_t s = 0; s < positions.size(); ++s) {
    ex.near.push_back(near_index.of(s));
    ex.wide.emplace_back(wide_index.of(s), ex.radius, ex.scene.dimension);
    std::sort(ex.near.back().begin(), ex.near.back().end(), by_key);
    const auto key = static_cast<std::size_t>(ex.samples.key[s]);
    if (ex.by_key.size() <= key) ex.by_key.resize(key + 1);
    ex.by_key[key].push_back(static_cast<int>(s));
  }
  return ex;
}

}  // namespace shapeproc::methods
