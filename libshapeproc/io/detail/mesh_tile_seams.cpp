#include "libshapeproc/io/detail/mesh_tile_seams.hpp"

#include <cmath>
#include <map>
#include <queue>
#include <tuple>

namespace shapeproc::io {

namespace {

constexpr double kSamePoint = 1e-6;  // of the window's diagonal

struct Link {
  int to;
  Eigen::Vector3i periods;  // `to` is moved by these periods relative to the piece linked from
};

}  // namespace

SeamJoin join_across_faces(const std::vector<geometry::Vec3>& points,
                           const std::vector<std::array<int, 3>>& triangles,
                           const std::vector<int>& piece_of_triangle, int pieces,
                           const geometry::Box3& window) {
  const geometry::Vec3 sizes = window.sizes();
  const double eps = kSamePoint * sizes.norm();
  std::vector<int> piece_of_vertex(points.size(), -1);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int v : triangles[f]) piece_of_vertex[static_cast<std::size_t>(v)] = piece_of_triangle[f];

  // Links between pieces across each pair of opposite faces: vertices on the high face indexed by
  // their other two coordinates on a grid of side eps (and its neighbours searched).
  std::vector<std::vector<Link>> links(static_cast<std::size_t>(pieces));
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    std::map<std::pair<long long, long long>, std::vector<int>> high;
    const auto cell = [&](const geometry::Vec3& p) {
      return std::make_pair(static_cast<long long>(std::floor(p[u] / eps)),
                            static_cast<long long>(std::floor(p[w] / eps)));
    };
    for (std::size_t v = 0; v < points.size(); ++v)
      if (piece_of_vertex[v] >= 0 && std::abs(points[v][axis] - window.max()[axis]) <= eps)
        high[cell(points[v])].push_back(static_cast<int>(v));
    for (std::size_t v = 0; v < points.size(); ++v) {
      if (piece_of_vertex[v] < 0 || std::abs(points[v][axis] - window.min()[axis]) > eps) continue;
      geometry::Vec3 image = points[v];
      image[axis] += sizes[axis];
      const auto [cu, cw] = cell(image);
      for (long long du = -1; du <= 1; ++du) {
        for (long long dw = -1; dw <= 1; ++dw) {
          const auto found = high.find({cu + du, cw + dw});
          if (found == high.end()) continue;
          for (int h : found->second) {
            if ((points[static_cast<std::size_t>(h)] - image).norm() > eps) continue;
            const int low_piece = piece_of_vertex[v];
            const int high_piece = piece_of_vertex[static_cast<std::size_t>(h)];
            Eigen::Vector3i step = Eigen::Vector3i::Zero();
            step[axis] = 1;
            links[static_cast<std::size_t>(high_piece)].push_back({low_piece, step});
            links[static_cast<std::size_t>(low_piece)].push_back({high_piece, -step});
          }
        }
      }
    }
  }

  // Pieces linked together are one element; a breadth-first walk gives each its periods.
  SeamJoin join;
  join.element_of_piece.assign(static_cast<std::size_t>(pieces), -1);
  join.periods_of_piece.assign(static_cast<std::size_t>(pieces), Eigen::Vector3i::Zero());
  for (int first = 0; first < pieces; ++first) {
    if (join.element_of_piece[static_cast<std::size_t>(first)] >= 0) continue;
    const int element = join.elements++;
    join.element_of_piece[static_cast<std::size_t>(first)] = element;
    std::queue<int> open;
    open.push(first);
    int members = 0;
    while (!open.empty()) {
      const int p = open.front();
      open.pop();
      ++members;
      for (const Link& link : links[static_cast<std::size_t>(p)]) {
        const Eigen::Vector3i periods =
            join.periods_of_piece[static_cast<std::size_t>(p)] + link.periods;
        int& other = join.element_of_piece[static_cast<std::size_t>(link.to)];
        if (other < 0) {
          other = element;
          join.periods_of_piece[static_cast<std::size_t>(link.to)] = periods;
          open.push(link.to);
        } else if (join.periods_of_piece[static_cast<std::size_t>(link.to)] != periods) {
          join.wraps = true;
        }
      }
    }
    if (members > 1) join.joined_pieces += members;
  }
  return join;
}

geometry::Vec3 wrap_into(const geometry::Vec3& position, const geometry::Box3& window) {
  geometry::Vec3 out = position;
  const geometry::Vec3 sizes = window.sizes();
  for (int a = 0; a < 3; ++a) {
    if (!(sizes[a] > 0)) continue;
    out[a] = window.min()[a] + (position[a] - window.min()[a]) -
             sizes[a] * std::floor((position[a] - window.min()[a]) / sizes[a]);
  }
  return out;
}

}  // namespace shapeproc::io
