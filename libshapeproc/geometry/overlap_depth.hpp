// Touching is not overlapping: how deep two element shapes overlap, for the signed shape
// distance (pair_measurements.hpp). The shape distance between outlines is 0 both when shapes
// touch and when they overlap; the signed distance is minus the overlap depth, so that a hard
// core at 0 forbids overlaps and keeps the contacts an exemplar has.
//
// The depth is the deepest proxy vertex of either shape lying inside the other (its distance to
// the other's outline or surface), a lower bound of the penetration depth that is exact when a
// corner pokes in. Outlines that cross with no vertex inside (two bars crossing as an X) get a
// depth of 1e-9 of the shapes' size: they overlap, by an amount this measure does not see.
#pragma once

#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::geometry {

// Shortest distance from p to the outline of a 2D proxy, or to the surface of a 3D proxy.
double point_to_outline(const Proxy2& proxy, const Vec2& p);
double point_to_surface(const Proxy3& proxy, const Vec3& p);

// Depth of the overlap of shape a at the origin and shape b at `offset`; 0 when their filled
// regions (2D) or solids (closed meshes, 3D) do not overlap with positive measure. Where the
// depth itself does not matter, only whether there is one, `any` stops at the first vertex found
// inside the other shape and returns its depth (positive, at most the overlap's).
double overlap_depth(const Proxy2& a, const Proxy2& b, const Vec2& offset, bool any = false);
double overlap_depth(const Proxy3& a, const Proxy3& b, const Vec3& offset, bool any = false);

}  // namespace shapeproc::geometry
