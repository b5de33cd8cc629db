#include "libshapeproc/methods/davison2018/detail/dbscan.hpp"

namespace shapeproc::methods {

namespace {

constexpr int kUnvisited = -2;

std::vector<int> within(const std::vector<geometry::Vec3>& points, std::size_t i, double eps2) {
  std::vector<int> out;
  for (std::size_t j = 0; j < points.size(); ++j)
    if ((points[j] - points[i]).squaredNorm() <= eps2) out.push_back(static_cast<int>(j));
  return out;
}

}  // namespace

std::vector<int> dbscan(const std::vector<geometry::Vec3>& points, double eps, int min_points) {
  const double eps2 = eps * eps;
  std::vector<int> label(points.size(), kUnvisited);
  int clusters = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (label[i] != kUnvisited) continue;
    std::vector<int> frontier = within(points, i, eps2);
    if (static_cast<int>(frontier.size()) < min_points) {
      label[i] = kNoise;
      continue;
    }
    const int cluster = clusters++;
    label[i] = cluster;
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      const auto j = static_cast<std::size_t>(frontier[f]);
      if (label[j] == kNoise) label[j] = cluster;  // a border point
      if (label[j] != kUnvisited) continue;
      label[j] = cluster;
      const std::vector<int> more = within(points, j, eps2);
      if (static_cast<int>(more.size()) >= min_points)
        frontier.insert(frontier.end(), more.begin(), more.end());
    }
  }
  return label;
}

}  // namespace shapeproc::methods
