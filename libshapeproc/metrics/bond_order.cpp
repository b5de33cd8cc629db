#include "libshapeproc/metrics/bond_order.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

#include "libshapeproc/geometry/nearest_neighbours.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"

namespace shapeproc::metrics {

namespace {

using Complex = std::complex<double>;

}  // namespace

BondOrder bond_order(const geometry::Scene& tile_or_scene, geometry::Boundary boundary) {
  if (!(tile_or_scene.window.sizes().x() > 0 && tile_or_scene.window.sizes().y() > 0))
    throw std::invalid_argument("bond order: the scene's window is empty");
  BondOrder out;
  // A torus of few elements is a seamless tile: repeated until it holds 7 or more, each element's
  // periodic images count as the neighbours they are.
  geometry::Scene repeated;
  const bool few = boundary == geometry::Boundary::torus && !tile_or_scene.elements.empty() &&
                   tile_or_scene.elements.size() < 7;
  if (few) {
    int times = 2;
    while (static_cast<std::size_t>(times * times) * tile_or_scene.elements.size() < 7) ++times;
    repeated = geometry::repeat_tile(tile_or_scene, times);
  }
  const geometry::Scene& scene = few ? repeated : tile_or_scene;
  if (scene.elements.size() < 7) return out;
  geometry::Box3 plane = scene.window;
  plane.min().z() = plane.max().z() = 0.0;
  const geometry::Domain domain(plane, 2, boundary);
  std::vector<geometry::Vec3> points;
  for (const geometry::Element& e : scene.elements)
    points.push_back(domain.wrap(geometry::Vec3(e.position.x(), e.position.y(), 0.0)));
  const auto near = geometry::nearest_offsets(points, domain, 6);
  const auto measure = [&](std::size_t symmetry, double& global, double& local) {
    // In an open window, an element nearer the edge than its n-th neighbour may miss nearer
    // neighbours beyond it: it is no centre (unless no element is far enough in).
    std::vector<std::size_t> centres;
    for (std::size_t i = 0; i < near.size(); ++i) {
      const geometry::Vec3& p = points[i];
      const double edge = std::min({p.x() - plane.min().x(), plane.max().x() - p.x(),
                                    p.y() - plane.min().y(), plane.max().y() - p.y()});
      if (domain.periodic() || near[i][symmetry - 1].norm() <= edge) centres.push_back(i);
    }
    if (centres.empty())
      for (std::size_t i = 0; i < near.size(); ++i) centres.push_back(i);
    Complex sum = 0.0;
    double magnitudes = 0.0;
    for (const std::size_t i : centres) {
      Complex psi = 0.0;
      for (std::size_t k = 0; k < symmetry; ++k)
        psi += std::polar(
            1.0, static_cast<double>(symmetry) * std::atan2(near[i][k].y(), near[i][k].x()));
      psi /= static_cast<double>(symmetry);
      sum += psi;
      magnitudes += std::abs(psi);
    }
    global = std::abs(sum) / static_cast<double>(centres.size());
    local = magnitudes / static_cast<double>(centres.size());
  };
  measure(4, out.global4, out.local4);
  measure(6, out.global6, out.local6);
  return out;
}

}  // namespace shapeproc::metrics
