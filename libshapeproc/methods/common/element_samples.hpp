// Element samples (Ma et al. 2011, §3.1): every element represented by one or several points whose
// positions carry its position, orientation and shape, so that the neighbourhood EM works on
// points only. A compact shape gets one sample at its reference position; an elongated or
// complex one gets several, spread along its principal axis and snapped to its proxy (the outline
// in 2D, the simplified mesh's vertices in 3D), numbered by sample id from one end to the other.
//
// A sample carries Ma's attributes q: its element, its sample id, and its element's category and
// shape class. Partners in the neighbourhood metric must share the key (sample count and sample
// id, so that an element's topology is never changed); category and shape class are the
// attribute that eq. 1 weighs with α.
#pragma once

#include <vector>

#include "libshapeproc/geometry/proxy.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::methods {

using geometry::Vec3;

inline constexpr int kMaxSamplesPerElement = 16;
// Proxy outlines (2D) and mesh edges (3D) are resampled at this many points per bounding-box
// diagonal, so that samples snap to the outline, not only to its corners, and elongation weighs
// the outline evenly.
inline constexpr double kOutlinePointsPerDiagonal = 64.0;

// The ratio of a point set's largest to smallest principal standard deviation (1: round; a
// segment's points: infinite, returned as 1e9).
double elongation(const std::vector<Vec3>& points, int dimension);

// Samples for an element of this elongation when the count is automatic: 1 below 2, then
// round(elongation) + 1 (a banana of elongation 4 gets 5, as in Ma et al.'s Table 1), at most 8.
int automatic_sample_count(double elongation);

// One shape's samples as offsets from the element's reference position, in sample-id order.
struct SampleTemplate {
  std::vector<Vec3> offsets;
};

// The points of a shape's proxy in local coordinates, resampled evenly: its outline in 2D, its
// mesh's vertices and edges in 3D; the origin for a point shape.
std::vector<Vec3> proxy_points(const geometry::Shape& shape, int dimension,
                               const geometry::ProxyOptions& options);

// The sample template of a shape with `count` samples (count 1: the reference position).
SampleTemplate sample_template(const std::vector<Vec3>& points, int dimension, int count);

// A scene's elements as samples, element by element.
struct ElementSamples {
  std::vector<Vec3> positions;
  std::vector<int> element;    // the element each sample belongs to
  std::vector<int> sample_id;  // its number within the element
  std::vector<int> key;        // sample count and sample id: partners share it
  std::vector<int> first;      // first sample of each element; first.back() = sample count

  std::size_t size() const { return positions.size(); }
  int count_of(int e) const {
    return first[static_cast<std::size_t>(e) + 1] - first[static_cast<std::size_t>(e)];
  }
};

// The key of sample `id` of an element with `count` samples.
inline int sample_key(int count, int id) { return count * kMaxSamplesPerElement + id; }

struct SampleOptions {
  int per_element = 0;  // 0: automatic from each shape's elongation
  geometry::ProxyOptions proxy;
};

// Every shape's template: `per_element` samples each, or one automatic count per category, from
// the median elongation of its elements (a category's elements then share their sample ids).
std::vector<SampleTemplate> sample_templates(const geometry::Scene& scene,
                                             const SampleOptions& options);

// The samples of `scene`'s elements, each placed by its shape's template.
ElementSamples place_samples(const geometry::Scene& scene,
                             const std::vector<SampleTemplate>& templates);

}  // namespace shapeproc::methods
