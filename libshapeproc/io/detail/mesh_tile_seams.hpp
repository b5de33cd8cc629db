// A mesh tile: the pieces of a 3D exemplar that is one period of a seamless repeat, cut by the
// faces of its box window, joined with their counterparts across the opposite faces into whole
// elements (the 3D side of `--tile`; the SVG reader joins 2D pieces the same way).
//
// A vertex on a low face (x = min) and one on the opposite high face at the same place one period
// away (within a millionth of the window's diagonal) are the same point of the repeat, so their
// pieces are one element; the piece on the low face is moved by one period to continue the other.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::io {

struct SeamJoin {
  std::vector<int> element_of_piece;              // pieces of one element share its index
  std::vector<Eigen::Vector3i> periods_of_piece;  // whole periods each piece is moved by
  int elements = 0;
  int joined_pieces = 0;  // pieces that joined another
  bool wraps = false;     // a motif that meets itself around the repeat (left as it joined first)
};

// `piece_of_triangle` numbers the pieces 0 .. pieces − 1.
SeamJoin join_across_faces(const std::vector<geometry::Vec3>& points,
                           const std::vector<std::array<int, 3>>& triangles,
                           const std::vector<int>& piece_of_triangle, int pieces,
                           const geometry::Box3& window);

// `position` moved by whole periods into [min, max) of the window.
geometry::Vec3 wrap_into(const geometry::Vec3& position, const geometry::Box3& window);

}  // namespace shapeproc::io
