// The state of a decomposed run (domain_decomposition.hpp): the elements of each cell, and one
// visit of a cell given the elements around it. A process holds the cells it owns
// (cell_partition.hpp), and copies of the cells around them that others own.
#pragma once

#include <cstdint>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/sample/cell_layout.hpp"
#include "libshapeproc/sample/cell_partition.hpp"
#include "libshapeproc/sample/move_counts.hpp"

namespace shapeproc::sample {

struct ChainTables;
struct ChainRegion;

// A visit's random seed, from the run's, the sweep, the colour and the cell (SplitMix64 of the
// parts): the same whatever process or thread makes the visit.
std::uint64_t visit_seed(std::uint64_t run, std::uint64_t sweep, std::uint64_t colour,
                         std::uint64_t cell);

// The output's mean nearest spacing as exact integer parts, so that sums over cells in any order
// and over any number of processes agree bit for bit: each element's distance to its nearest
// other, capped, in units of cap / 2^30.
struct SpacingSum {
  long long units = 0;
  long long elements = 0;
};

class DecomposedCells {
 public:
  static constexpr double kSpacingUnits = 1073741824.0;  // 2^30 units per cap

  DecomposedCells(const ChainTables& tables, const ChainRegion& whole, CellLayout layout,
                  double density, CellPartition& partition);

  const CellLayout& layout() const { return layout_; }
  CellPartition& partition() { return partition_; }

  // Shifts the cells' boundaries by `offset` and moves each element this process holds to the
  // cell that now holds it, handing those of other processes' cells on to them.
  void shift(const geometry::Vec3& offset);
  // Copies into the cells around this process's own the current elements of their owners.
  void refresh_borders() { partition_.refresh_borders(cells_); }
  // Adds elements to the cells that hold them (a start; all of them this process's own).
  void place(const std::vector<geometry::Element>& elements);

  // This process's own elements, by cell, each cell's in its order.
  std::vector<geometry::Element> own_elements() const;
  long long own_size() const;
  // Start elements the hard core refused in this process's visits so far.
  int left_out() const;

  // The steps of a visit: fixed by the pilot's density and the cell's measure.
  long long visit_steps(int cell) const;

  // Updates `cell` given the elements around it: `steps` birth-death steps, or (fill) random
  // sequential insertion up to the pilot's density. Only the cell's own list changes, so cells of
  // one colour may be visited at once.
  MoveCounts visit(int cell, long long steps, bool fill, std::uint64_t seed);

  // Each element of `cell` at its distance to the nearest other element, among those of the cell
  // and the cells around it, capped at the cells' shortest side (which all those cells cover).
  SpacingSum spacing(int cell) const;
  double spacing_cap() const;

 private:
  double measure(int cell) const;

  const ChainTables& tables_;
  const ChainRegion& whole_;
  CellLayout layout_;
  double density_;
  CellPartition& partition_;
  std::vector<std::vector<geometry::Element>> cells_;  // own cells, and copies around them
  std::vector<int> left_out_;                          // per cell
};

}  // namespace shapeproc::sample
