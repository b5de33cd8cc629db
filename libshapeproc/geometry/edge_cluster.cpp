#include "libshapeproc/geometry/edge_cluster.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::geometry {

namespace {

std::array<double, kClusterMonomials> monomials(const Vec2& u) {
  const double x = u.x(), y = u.y();
  return {1.0, x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y};
}

void split(const std::vector<Vec2>& start, const std::vector<Vec2>& end, std::vector<int>& edges,
           std::size_t first, std::size_t last, std::size_t size,
           std::vector<std::vector<int>>& groups) {
  if (last - first <= size) {
    groups.emplace_back(edges.begin() + static_cast<std::ptrdiff_t>(first),
                        edges.begin() + static_cast<std::ptrdiff_t>(last));
    return;
  }
  const auto mid = [&](int j) -> Vec2 {
    return 0.5 * (start[static_cast<std::size_t>(j)] + end[static_cast<std::size_t>(j)]);
  };
  Box2 box;
  for (std::size_t k = first; k < last; ++k) box.extend(mid(edges[k]));
  const int axis = box.sizes().x() >= box.sizes().y() ? 0 : 1;
  const std::size_t half = first + (last - first) / 2;
  // Ties broken by index, so that the groups do not depend on the library's partition order.
  std::nth_element(edges.begin() + static_cast<std::ptrdiff_t>(first),
                   edges.begin() + static_cast<std::ptrdiff_t>(half),
                   edges.begin() + static_cast<std::ptrdiff_t>(last), [&](int a, int b) {
                     const double pa = mid(a)[axis], pb = mid(b)[axis];
                     return pa < pb || (pa == pb && a < b);
                   });
  split(start, end, edges, first, half, size, groups);
  split(start, end, edges, half, last, size, groups);
}

}  // namespace

void EdgeCluster::add_edge(const Vec2& a, const Vec2& b, const Vec2& n) {
  // Two Gauss–Legendre points integrate the cubic monomials exactly.
  constexpr double kOffset = 0.2886751345948129;  // 1/(2√3)
  const double half_length = 0.5 * (b - a).norm();
  for (const double t : {0.5 - kOffset, 0.5 + kOffset}) {
    const auto m = monomials(a + t * (b - a) - centre);
    for (int k = 0; k < kClusterMonomials; ++k) {
      moments[0][static_cast<std::size_t>(k)] +=
          half_length * n.x() * m[static_cast<std::size_t>(k)];
      moments[1][static_cast<std::size_t>(k)] +=
          half_length * n.y() * m[static_cast<std::size_t>(k)];
    }
  }
  radius = std::max({radius, (a - centre).norm(), (b - centre).norm()});
}

double EdgeCluster::potential(const Vec2& x) const {
  const double a = centre.x() - x.x(), b = centre.y() - x.y();
  const double d2 = a * a + b * b;
  const double inv = 1.0 / std::sqrt(d2), inv2 = inv * inv;
  const double inv3 = inv * inv2, inv5 = inv3 * inv2, inv7 = inv5 * inv2;
  // The coefficients of 1/|d + u| on the monomials of u (see the header).
  const std::array<double, kClusterMonomials> c = {inv,
                                                   -a * inv3,
                                                   -b * inv3,
                                                   0.5 * (3 * a * a - d2) * inv5,
                                                   3 * a * b * inv5,
                                                   0.5 * (3 * b * b - d2) * inv5,
                                                   -0.5 * (5 * a * a * a - 3 * d2 * a) * inv7,
                                                   -0.5 * (15 * a * a * b - 3 * d2 * b) * inv7,
                                                   -0.5 * (15 * a * b * b - 3 * d2 * a) * inv7,
                                                   -0.5 * (5 * b * b * b - 3 * d2 * b) * inv7};
  // n·(d + u) / |d + u| = d_k n_k / |d + u| + n_k u_k / |d + u|; the second term's monomials are
  // one degree higher in u_k, so it takes the coefficients up to degree 2.
  constexpr std::array<int, 6> kTimesX = {1, 3, 4, 6, 7, 8}, kTimesY = {2, 4, 5, 7, 8, 9};
  double along_x = 0.0, along_y = 0.0, own = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    along_x += c[k] * moments[0][k];
    along_y += c[k] * moments[1][k];
  }
  for (std::size_t k = 0; k < kTimesX.size(); ++k) {
    own += c[k] * (moments[0][static_cast<std::size_t>(kTimesX[k])] +
                   moments[1][static_cast<std::size_t>(kTimesY[k])]);
  }
  return a * along_x + b * along_y + own;
}

std::vector<std::vector<int>> group_nearby_edges(const std::vector<Vec2>& start,
                                                 const std::vector<Vec2>& end,
                                                 std::vector<int> edges, std::size_t size) {
  std::vector<std::vector<int>> groups;
  if (!edges.empty())
    split(start, end, edges, 0, edges.size(), std::max<std::size_t>(size, 1), groups);
  return groups;
}

}  // namespace shapeproc::geometry
