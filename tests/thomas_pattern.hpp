// A Thomas cluster pattern for the tests: 10 parents uniform in [10, 90]², 12 children each,
// offset from their parent by normal draws of σ = 2 (Box–Muller), on the window [0, 100]², those
// outside it dropped. With several categories, each child is of category k with probability
// shares[k]; with one, no draw is made for it.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::testing {

inline geometry::Scene thomas_pattern(std::uint64_t seed,
                                      const std::vector<std::string>& categories = {"point"},
                                      const std::vector<double>& shares = {1.0}) {
  using geometry::Vec3;
  geometry::Scene scene;
  scene.window = geometry::Box3(Vec3(0, 0, 0), Vec3(100, 100, 0));
  for (const std::string& name : categories) scene.category_index(name);
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  core::Random random(seed);
  for (int parent = 0; parent < 10; ++parent) {
    const Vec3 centre(random.uniform(10, 90), random.uniform(10, 90), 0);
    for (int child = 0; child < 12; ++child) {
      const double r = 2.0 * std::sqrt(-2 * std::log(1 - random.uniform()));
      const double a = 2 * 3.14159265358979 * random.uniform();
      int category = 0;
      if (categories.size() > 1) {
        double u = random.uniform();
        while (category + 1 < static_cast<int>(shares.size()) && u >= shares[category])
          u -= shares[category++];
      }
      const Vec3 p = centre + Vec3(r * std::cos(a), r * std::sin(a), 0);
      if (p.x() >= 0 && p.x() <= 100 && p.y() >= 0 && p.y() <= 100)
        scene.elements.push_back({0, category, p});
    }
  }
  return scene;
}

// The exemplar fitted as `synthesize` fits it, without the maximum likelihood.
inline fit::ExemplarFit fit_by_pseudo_likelihood(const geometry::Scene& exemplar) {
  fit::ExemplarFitOptions options;
  options.likelihood.reset();
  return fit::fit_exemplar(exemplar, options);
}

}  // namespace shapeproc::testing
