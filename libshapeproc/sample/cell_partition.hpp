// How the cells of a decomposed run are shared among processes (docs/sample.md, "Sampling across
// processes"). Each process holds and visits the cells it owns. Between visits it does three
// things: it hands on the elements that a shift of the cells moved into another's cells, it
// refreshes the cells around its own from their owners, and it sums the run's counts over all
// processes. A run without a partition is one process that owns every cell (OneProcess). The
// distributed module's MPI partition gives each rank a block of cells.
#pragma once

#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::sample {

class CellLayout;

// An element leaving for a cell another process owns. It carries the cell it was in and its
// place there, so that the receiving cell lists its elements in the order one process would
// have: by former cell, then by place in it.
struct MovingElement {
  geometry::Element element;
  int from_cell = 0;
  int place = 0;
};

class CellPartition {
 public:
  virtual ~CellPartition() = default;

  // Called once the run's cells are known (their number, not yet their offset).
  virtual void plan(const CellLayout& layout) = 0;
  virtual int processes() const = 0;
  virtual int owner(int cell) const = 0;
  bool owns(int cell) const { return owner(cell) == rank(); }
  virtual int rank() const = 0;

  // Sends outgoing[p] to process p and returns what the others sent here, in any order.
  virtual std::vector<MovingElement> exchange_moving(
      std::vector<std::vector<MovingElement>> outgoing) = 0;
  // Writes into `cells` (indexed by cell) the current elements of every cell that lies around one
  // of this process's own and that another process owns.
  virtual void refresh_borders(std::vector<std::vector<geometry::Element>>& cells) = 0;
  // Sums over all processes (exact, whatever their number).
  virtual long long sum(long long value) = 0;
  // Whether any process says yes (a cancelled run stops everywhere at once).
  virtual bool any(bool value) = 0;
};

// One process owning every cell: nothing to exchange.
class OneProcess final : public CellPartition {
 public:
  void plan(const CellLayout&) override {}
  int processes() const override { return 1; }
  int owner(int) const override { return 0; }
  int rank() const override { return 0; }
  std::vector<MovingElement> exchange_moving(std::vector<std::vector<MovingElement>>) override {
    return {};
  }
  void refresh_borders(std::vector<std::vector<geometry::Element>>&) override {}
  long long sum(long long value) override { return value; }
  bool any(bool value) override { return value; }
};

}  // namespace shapeproc::sample
