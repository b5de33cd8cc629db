// What the neighbourhood EM (Ma et al. 2011) learns from an exemplar, once: its elements as
// samples, their attributes, the neighbourhood size and every sample's neighbourhood.
//
// The neighbourhood size is given in rings: r = (rings + 1/2) d̄, d̄ the exemplar's mean nearest
// distance between element reference positions, so that 1 ring holds the nearest neighbours
// (Ma et al. §6.2 use 1 to 3 rings; the default is 2). Each sample has two neighbourhoods: the
// ordinary one (radius r), used where the sample is the output side of eq. 1 (similarity sets,
// the domain term), and a wide one (radius 2r) that stands for Ma's neighbourhood of unbounded
// extent on the exemplar side: with pair costs capped at r², no partner farther out could count.
#pragma once

#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/element_neighbourhood.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/methods/common/element_samples.hpp"

namespace shapeproc::methods {

struct EmExemplar {
  geometry::Scene scene;  // a seamless tile smaller than 4r: repeated until it is not
  geometry::Boundary boundary = geometry::Boundary::open;
  // A seamless tile's own period (its window's sizes before any repeat), zero for an open
  // exemplar: two elements one or more periods apart are the same element of the drawing.
  geometry::Vec3 tile_period = geometry::Vec3::Zero();
  // Whether two samples are the same sample of the drawing: equal, or of the same shape and
  // whole tile periods apart.
  bool same_place(int a, int b) const;
  std::vector<SampleTemplate> templates;  // per shape
  ElementSamples samples;
  // Per element: category, shape class (identical shapes, or size groups: fit/shape_classes) and
  // the attribute code q that combines them.
  std::vector<int> category, shape_class, attribute;
  std::vector<int> sample_attribute;                 // per sample: its element's attribute
  double spacing = 0.0;                              // d̄, the mean nearest distance
  double radius = 0.0;                               // r
  double density = 0.0;                              // elements per unit area (volume)
  std::vector<geometry::Neighbourhood> near;         // per sample: radius r
  std::vector<geometry::PairingNeighbourhood> wide;  // per sample: radius 2r, for pairing
  // Samples by key (what a centre may be matched to).
  std::vector<std::vector<int>> by_key;  // indexed by key; empty where no sample has it

  // The distance between two attribute codes (eq. 5's |q − q'|²): one per differing part.
  double attribute_distance(int element_a, int element_b) const;
  const std::vector<int>& samples_with_key(int key) const;
};

// Per element: its category, shape class (identical shapes, or size groups: fit/shape_classes;
// -1 when the scene has no shapes to class) and the attribute code that combines them.
struct ElementClasses {
  std::vector<int> category, shape_class, attribute;
};
ElementClasses classify_elements(const geometry::Scene& scene);

// The mean distance from each element's reference position to its nearest other's (minimum image
// on a torus); 0 for a single element.
double mean_nearest_distance(const std::vector<geometry::Element>& elements,
                             const geometry::Domain& domain);

// Analyses `scene` (its window a torus or open, as `boundary` says) for a neighbourhood of
// `rings` rings. Throws core::ArgumentError for an exemplar with fewer than 2 elements.
EmExemplar analyse_exemplar(const geometry::Scene& scene, geometry::Boundary boundary, double rings,
                            const SampleOptions& options);

}  // namespace shapeproc::methods
