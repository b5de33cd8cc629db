#include "libshapeproc/distributed/mpi_cell_partition.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/sample/cell_layout.hpp"

namespace shapeproc::distributed {

namespace {

// An element as it travels: plain numbers, the same on every rank of one machine type.
struct Packed {
  double x, y, z;
  int shape, category, from_cell, place;
};

Packed pack(const sample::MovingElement& m) {
  const geometry::Element& e = m.element;
  return {e.position.x(), e.position.y(), e.position.z(), e.shape,
          e.category,     m.from_cell,    m.place};
}

sample::MovingElement unpack(const Packed& p) {
  sample::MovingElement m;
  m.element.position = geometry::Vec3(p.x, p.y, p.z);
  m.element.shape = p.shape;
  m.element.category = p.category;
  m.from_cell = p.from_cell;
  m.place = p.place;
  return m;
}

template <class T>
void append(std::vector<char>& bytes, const T& value) {
  const auto* start = reinterpret_cast<const char*>(&value);
  bytes.insert(bytes.end(), start, start + sizeof(T));
}

template <class T>
T read(const std::vector<char>& bytes, std::size_t& at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS)
    throw core::ArgumentError("distributed", std::string("MPI ") + what + " failed");
}

}  // namespace

MpiCellPartition::MpiCellPartition(MPI_Comm communicator) : communicator_(communicator) {
  check(MPI_Comm_rank(communicator_, &rank_), "rank");
  check(MPI_Comm_size(communicator_, &size_), "size");
}

void MpiCellPartition::plan(const sample::CellLayout& layout) {
  const Eigen::Vector3i& per_axis = layout.per_axis();
  axis_ = 0;
  for (int a = 2; a >= 0; --a) {
    if (per_axis[a] > 1) {
      axis_ = a;
      break;
    }
  }
  rows_ = per_axis[axis_];
  if (rows_ < size_)
    throw core::ArgumentError(
        "distributed", std::to_string(size_) + " ranks need at least as many rows of cells; the " +
                           "output has " + std::to_string(rows_) +
                           " along its outermost cut axis: give a larger --size or fewer ranks");
  first_row_.resize(static_cast<std::size_t>(size_) + 1);
  for (int r = 0; r <= size_; ++r)
    first_row_[static_cast<std::size_t>(r)] =
        static_cast<int>(static_cast<long long>(r) * rows_ / size_);
  row_of_cell_.resize(static_cast<std::size_t>(layout.count()));
  for (int c = 0; c < layout.count(); ++c)
    row_of_cell_[static_cast<std::size_t>(c)] = layout.index_of(c)[axis_];
  // Cells around a cell are around it both ways: what a rank reads of another is what it sends.
  send_cells_.assign(static_cast<std::size_t>(size_), {});
  receive_cells_.assign(static_cast<std::size_t>(size_), {});
  for (int c = 0; c < layout.count(); ++c) {
    if (owner(c) != rank_) continue;
    for (int other : layout.around(c)) {
      const int q = owner(other);
      if (q == rank_) continue;
      send_cells_[static_cast<std::size_t>(q)].push_back(c);
      receive_cells_[static_cast<std::size_t>(q)].push_back(other);
    }
  }
  for (auto* lists : {&send_cells_, &receive_cells_})
    for (std::vector<int>& list : *lists) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
}

int MpiCellPartition::owner(int cell) const {
  const int row = row_of_cell_[static_cast<std::size_t>(cell)];
  return static_cast<int>(std::upper_bound(first_row_.begin(), first_row_.end(), row) -
                          first_row_.begin()) -
         1;
}

std::vector<std::vector<char>> MpiCellPartition::exchange(
    const std::vector<std::vector<char>>& bytes) const {
  const auto n = static_cast<std::size_t>(size_);
  std::vector<int> send_counts(n), receive_counts(n), send_at(n), receive_at(n);
  std::vector<char> sent;
  for (std::size_t p = 0; p < n; ++p) {
    send_at[p] = static_cast<int>(sent.size());
    send_counts[p] = static_cast<int>(bytes[p].size());
    sent.insert(sent.end(), bytes[p].begin(), bytes[p].end());
  }
  bytes_sent_ += static_cast<long long>(sent.size());
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT,
                     communicator_),
        "all-to-all");
  int total = 0;
  for (std::size_t p = 0; p < n; ++p) {
    receive_at[p] = total;
    total += receive_counts[p];
  }
  std::vector<char> received(static_cast<std::size_t>(total));
  check(MPI_Alltoallv(sent.data(), send_counts.data(), send_at.data(), MPI_BYTE, received.data(),
                      receive_counts.data(), receive_at.data(), MPI_BYTE, communicator_),
        "all-to-all");
  std::vector<std::vector<char>> out(n);
  for (std::size_t p = 0; p < n; ++p)
    out[p].assign(received.begin() + receive_at[p],
                  received.begin() + receive_at[p] + receive_counts[p]);
  return out;
}

std::vector<sample::MovingElement> MpiCellPartition::exchange_moving(
    std::vector<std::vector<sample::MovingElement>> outgoing) {
  std::vector<std::vector<char>> bytes(static_cast<std::size_t>(size_));
  for (std::size_t p = 0; p < bytes.size(); ++p)
    for (const sample::MovingElement& m : outgoing[p]) append(bytes[p], pack(m));
  std::vector<sample::MovingElement> in;
  for (const std::vector<char>& from : exchange(bytes)) {
    for (std::size_t at = 0; at < from.size();) in.push_back(unpack(read<Packed>(from, at)));
  }
  return in;
}

void MpiCellPartition::refresh_borders(std::vector<std::vector<geometry::Element>>& cells) {
  std::vector<std::vector<char>> bytes(static_cast<std::size_t>(size_));
  for (std::size_t p = 0; p < bytes.size(); ++p) {
    for (const int c : send_cells_[p]) {
      const auto& cell = cells[static_cast<std::size_t>(c)];
      append(bytes[p], static_cast<int>(cell.size()));
      for (const geometry::Element& e : cell) append(bytes[p], pack({e, c, 0}));
    }
  }
  const std::vector<std::vector<char>> received = exchange(bytes);
  for (std::size_t p = 0; p < received.size(); ++p) {
    std::size_t at = 0;
    for (const int c : receive_cells_[p]) {
      auto& cell = cells[static_cast<std::size_t>(c)];
      cell.clear();
      const int count = read<int>(received[p], at);
      for (int k = 0; k < count; ++k) cell.push_back(unpack(read<Packed>(received[p], at)).element);
    }
  }
}

long long MpiCellPartition::sum(long long value) {
  long long total = 0;
  check(MPI_Allreduce(&value, &total, 1, MPI_LONG_LONG, MPI_SUM, communicator_), "sum");
  return total;
}

bool MpiCellPartition::any(bool value) {
  int mine = value ? 1 : 0, all = 0;
  check(MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LOR, communicator_), "reduction");
  return all != 0;
}

}  // namespace shapeproc::distributed
