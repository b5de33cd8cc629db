// Test helper: the pairs of a sampled scene that break the hard core of the model's first
// interaction (a shape distance below the axis's first threshold), as "i j" strings.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::testing {

inline std::vector<std::string> hard_core_violations(const geometry::Scene& scene,
                                                     const model::ShapeProcessModel& m) {
  std::vector<std::string> broken;
  const geometry::PairMeasurer measurer(scene, m.measurement_options(true));
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.elements.size(); ++j) {
      const geometry::Measurement pair = measurer.measure(scene.elements[i], scene.elements[j]);
      if (pair.distance < m.interactions[0].axes[static_cast<std::size_t>(pair.axis)].thresholds[0])
        broken.push_back(std::to_string(i) + " " + std::to_string(j));
    }
  }
  return broken;
}

}  // namespace shapeproc::testing
