// The cells of a decomposed run shared among the ranks of an MPI communicator (docs/sample.md,
// "Sampling across processes"). The cells are cut into rows along their outermost axis (z in
// 3D, y in 2D, or the next axis when that one is not cut). Rank r owns rows
// [⌊r R / P⌋, ⌊(r + 1) R / P⌋) of R rows among P ranks: a contiguous range of cell numbers, so
// the ranks' outputs in rank order are the cells in order. Between visits a rank sends its
// neighbours the elements that a shift moved into their rows, and the rows next to theirs, the
// only ones their visits read: no rank holds more than its block and the rows around it.
#pragma once

#include <mpi.h>

#include <vector>

#include "libshapeproc/sample/cell_partition.hpp"

namespace shapeproc::distributed {

class MpiCellPartition final : public sample::CellPartition {
 public:
  explicit MpiCellPartition(MPI_Comm communicator);

  // Throws core::ArgumentError when there are more ranks than rows of cells.
  void plan(const sample::CellLayout& layout) override;
  int processes() const override { return size_; }
  int rank() const override { return rank_; }
  int owner(int cell) const override;

  std::vector<sample::MovingElement> exchange_moving(
      std::vector<std::vector<sample::MovingElement>> outgoing) override;
  void refresh_borders(std::vector<std::vector<geometry::Element>>& cells) override;
  long long sum(long long value) override;
  bool any(bool value) override;

  // Bytes this rank has sent to others (elements moving, border cells) so far.
  long long bytes_sent() const { return bytes_sent_; }
  // The axis the rows run across, and the number of rows.
  int axis() const { return axis_; }
  int rows() const { return rows_; }

 private:
  // Sends `bytes[p]` to each rank p and returns what each sent here.
  std::vector<std::vector<char>> exchange(const std::vector<std::vector<char>>& bytes) const;

  MPI_Comm communicator_;
  int rank_ = 0, size_ = 1;
  int axis_ = 0, rows_ = 1;
  mutable long long bytes_sent_ = 0;
  std::vector<int> row_of_cell_;
  std::vector<int> first_row_;  // per rank, and one past the last
  // Per rank p: the cells of this rank that p's visits read, and the cells of p that this rank's
  // visits read.
  std::vector<std::vector<int>> send_cells_, receive_cells_;
};

}  // namespace shapeproc::distributed
