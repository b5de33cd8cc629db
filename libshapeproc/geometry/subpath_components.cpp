#include "libshapeproc/geometry/subpath_components.hpp"

#include <cmath>
#include <limits>
#include <numeric>

namespace shapeproc::geometry {

namespace {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

std::vector<Drawable2> split_disjoint_subpaths(const Drawable2& drawable) {
  const std::size_t n = drawable.paths.size();
  if (n <= 1) return {drawable};

  std::vector<std::vector<Vec2>> polylines(n);
  std::vector<Box2> boxes(n);
  std::vector<double> areas(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    boxes[i] = bounding_box(drawable.paths[i]);
    const double size = boxes[i].isEmpty() ? 0.0 : boxes[i].diagonal().norm();
    polylines[i] = flatten(drawable.paths[i], std::max(size * 1e-3, 1e-9));
    if (drawable.paths[i].closed) areas[i] = std::abs(signed_area(polylines[i]));
  }

  UnionFind pieces(n);
  std::vector<bool> crosses_any(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!boxes[i].intersects(boxes[j])) continue;
      if (polylines_overlap(polylines[i], drawable.paths[i].closed, polylines[j],
                            drawable.paths[j].closed)) {
        pieces.unite(i, j);
      }
    }
  }
  // Nesting: subpath i is inside closed subpath j when a point of i is inside j's polygon and
  // i is smaller. Their outlines do not cross (crossing pairs are already united), so one vertex
  // decides.
  for (std::size_t i = 0; i < n; ++i) {
    if (polylines[i].empty()) continue;
    int depth = 0;
    std::size_t innermost = n;
    double innermost_area = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || !drawable.paths[j].closed || polylines[j].size() < 3) continue;
      if (!boxes[j].contains(boxes[i])) continue;
      if (areas[j] <= areas[i]) continue;
      if (winding_number(polylines[j], polylines[i].front()) == 0) continue;
      ++depth;
      if (areas[j] < innermost_area) {
        innermost_area = areas[j];
        innermost = j;
      }
    }
    if (depth % 2 == 1) pieces.unite(i, innermost);
  }

  std::vector<Drawable2> result;
  std::vector<std::size_t> piece_of_root(n, std::numeric_limits<std::size_t>::max());
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = pieces.find(i);
    if (piece_of_root[root] == std::numeric_limits<std::size_t>::max()) {
      piece_of_root[root] = result.size();
      Drawable2 piece;
      piece.fill_rule = drawable.fill_rule;
      piece.style = drawable.style;
      result.push_back(std::move(piece));
    }
    result[piece_of_root[root]].paths.push_back(drawable.paths[i]);
  }
  return result;
}

}  // namespace shapeproc::geometry
