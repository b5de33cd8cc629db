#include "libshapeproc/methods/davison2018/density_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libshapeproc/core/format.hpp"

namespace shapeproc::methods {

namespace {

// A torus holding about kPilotElements at the exemplar's density, at least two and a half
// neighbourhood radii across (so that no neighbourhood meets its own image) and no larger than
// the output along any side.
geometry::Domain pilot_domain(const GrowthExemplar& exemplar, const geometry::Domain& output) {
  const int d = output.dimension();
  const double density = exemplar.part_density.front();
  double side = std::pow(kPilotElements / density, 1.0 / d);
  side = std::max(side, 2.5 * exemplar.em.radius);
  geometry::Box3 box = output.box();
  for (int a = 0; a < d; ++a) box.max()[a] = box.min()[a] + std::min(side, output.box().sizes()[a]);
  return geometry::Domain(box, d, geometry::Boundary::torus);
}

}  // namespace

std::string DensityCalibration::summary() const {
  if (pilots.empty()) return "not calibrated";
  const auto limit = [](double c) {
    return std::isfinite(c) ? "×" + core::format_general(c, 3) : std::string("none");
  };
  std::string s = limit(crowding) + " (" + std::to_string(pilots.size()) + " pilot" +
                  (pilots.size() == 1 ? "" : "s") + ":";
  for (std::size_t i = 0; i < pilots.size(); ++i)
    s += std::string(i ? "," : "") + " density ×" + core::format_general(pilots[i].ratio, 3) +
         (std::isfinite(pilots[i].crowding) ? " at ×" + core::format_general(pilots[i].crowding, 3)
                                            : " without");
  return s + ")";
}

DensityCalibration calibrate_density(const GrowthExemplar& exemplar, const GrowthOptions& options,
                                     const geometry::Domain& output, core::Random& random,
                                     const PilotGrowth& grow) {
  DensityCalibration c;
  if (options.bounding_radius > 0 || exemplar.parts() != 1 || !options.calibrate_density) return c;
  const geometry::Domain pilot = pilot_domain(exemplar, output);
  const double expected = exemplar.part_density.front() * pilot.measure();
  core::Random pilots(random.index(std::numeric_limits<std::uint64_t>::max()));
  double crowding = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kMostPilots; ++i) {
    const double ratio = static_cast<double>(grow(crowding, pilot, pilots)) / expected;
    c.pilots.push_back({crowding, ratio});
    if (std::abs(ratio - 1.0) <= kCalibrationTolerance) break;
    if (ratio < 1.0 && !std::isfinite(crowding)) break;  // as sparse as the exemplar: no limit
    crowding = std::isfinite(crowding) ? std::max(kFewestNeighbours, crowding / ratio) : 1.0;
  }
  // The pilot closest to the exemplar's density, of those grown.
  const auto best = std::min_element(
      c.pilots.begin(), c.pilots.end(), [](const DensityCalibration::Pilot& a, const auto& b) {
        return std::abs(std::log(a.ratio)) < std::abs(std::log(b.ratio));
      });
  c.crowding = best->crowding;
  return c;
}

}  // namespace shapeproc::methods
