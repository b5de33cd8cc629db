// A table of gravitation forces per pair of shapes on a grid of offsets, filled on first use: the
// axis bin of a detailed pair's direction read from it instead of the boundary integrals.
//
// The force F(t) between shape a at the origin and shape b at offset t is smooth in t. The table
// keeps its exact value at the points of a square (2D) or cubic (3D) grid of pitch h; at an offset
// t between grid points it interpolates them (bilinear, trilinear), F̃(t) = Σ_k w_k F(g_k). The
// corners' directions spread by an angle s about F̃'s, and the exact direction is taken to lie
// within w = 2s + 0.005 rad of F̃'s: the table answers only when every direction within w of F̃'s
// falls in the same axis bin (DirectionBins), and otherwise, or when a corner's force is too small
// to have a direction, leaves the pair to the exact force. Tests check the answers against the
// exact axes. The 0.005 rad is the exact force's own rounding: it is a sum of Gauss rules and
// expansions whose switches with distance move its direction by a few thousandths of a radian
// (with a margin of 1e-4 rad, a table of thin bars gave axes that differ from the exact ones
// within 0.15° of a bin's edge).
//
// A grid costs an exact force per point, so it pays only for pairs queried many times over the
// offsets they meet: a pair's grid opens after kOpenAfter queries, and until then the caller
// computes every direction exactly. Answers equal the exact axes either way, so results do not
// depend on threads or on the order of queries. The table stops growing at a number of points;
// beyond it, a query that needs a missing point is left to the caller.
//
// The grid is stored in blocks of 16 × 16 (2D) or 8 × 8 × 8 (3D) points, allocated when a query
// first reaches them and filled point by point: a query's corners are almost always in one block,
// so it costs one lookup of the block (most often in a small per-thread cache of recent blocks)
// instead of one locked hash lookup per corner. A point is written once, by the thread that
// claims it; the others read it only once it is marked ready.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "libshapeproc/geometry/directions.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

class ForceTable {
 public:
  // 25 bytes a slot of a block, and at most kSlotsPerPoint slots a point: 1M points is at most
  // about 75 MB.
  static constexpr std::size_t kDefaultMaxPoints = std::size_t{1} << 20;
  static constexpr std::size_t kSlotsPerPoint = 3;
  static constexpr std::uint32_t kOpenAfter = 4000;

  // `dimension` 2 or 3; `pairs` numbered 0..pairs−1; directions binned by `bins`.
  ForceTable(int dimension, const DirectionBins& bins, std::size_t pairs,
             std::size_t max_points = kDefaultMaxPoints, std::uint32_t open_after = kOpenAfter);
  ~ForceTable();
  ForceTable(const ForceTable&) = delete;
  ForceTable& operator=(const ForceTable&) = delete;

  // The axis bin of the force's direction at `offset` for pair `pair`, from the grid of pitch
  // `pitch` around it, when the pair's grid is open and vouches for it; nullopt otherwise.
  // `exact(g)` is the exact force at a grid point's offset g; `negligible` the norm below which a
  // force has no direction.
  std::optional<int> axis(std::size_t pair, double pitch, const Vec3& offset, double negligible,
                          const std::function<Vec3(const Vec3&)>& exact) const;

  // Grid points held, and queries answered from the grids (the rest fell back to the caller).
  std::size_t points() const { return held_.load(std::memory_order_relaxed); }
  std::size_t answered() const { return answered_.load(std::memory_order_relaxed); }
  std::size_t queries() const { return queries_.load(std::memory_order_relaxed); }

 private:
  struct Block;
  struct Shards;
  // The block holding grid point `index` of `pair` (its slot in `slot`), allocated if the table
  // has room; nullptr if it has none.
  Block* block_of(std::size_t pair, const std::array<std::int32_t, 3>& index,
                  std::size_t& slot) const;
  std::optional<Vec3> point(std::size_t pair, const std::array<std::int32_t, 3>& index,
                            double pitch, const std::function<Vec3(const Vec3&)>& exact) const;
  std::optional<int> vouched_axis(const Vec3& estimate, double spread) const;

  int dimension_;
  int side_;  // points along each axis of a block
  std::size_t block_slots_;
  std::uint64_t id_;  // unique among the tables a process makes (the per-thread block cache's key)
  DirectionBins bins_;
  std::size_t max_points_;
  std::uint32_t open_after_;
  std::unique_ptr<std::atomic<std::uint32_t>[]> pair_queries_;
  std::size_t pairs_;
  std::unique_ptr<Shards> shards_;
  mutable std::atomic<std::size_t> held_{0}, slots_{0}, answered_{0}, queries_{0};
};

}  // namespace shapeproc::geometry
