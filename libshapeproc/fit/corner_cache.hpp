// The samples at quadrature cell corners (2D), shared by the cells that meet there.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace shapeproc::fit {

// Distances and directions of one neighbour measured at a cell corner (2D), kept for the other
// cells that meet there. One per thread; the results do not depend on it. An open-addressing
// table whose clear() is one increment (a block of rows clears it thousands of times).
class CornerCache {
 public:
  struct Key {
    int shape, neighbour;
    long x, y;
    int image_x, image_y;
    bool operator==(const Key& o) const {
      return shape == o.shape && neighbour == o.neighbour && x == o.x && y == o.y &&
             image_x == o.image_x && image_y == o.image_y;
    }
  };
  // The value stored under `key` (distances and angles apart), measure() the first time.
  template <class Measure>
  double distance(const Key& key, Measure&& measure) {
    return lookup(key, 0, measure);
  }
  template <class Measure>
  double angle(const Key& key, Measure&& measure) {
    return lookup(key, 1, measure);
  }
  void clear() {
    if (++generation_ == 0) {  // wrapped around: no slot may look used
      std::fill(slots_.begin(), slots_.end(), Slot{});
      generation_ = 1;
    }
    size_ = 0;
  }
  std::size_t size() const { return size_; }

 private:
  struct Slot {
    Key key;
    int kind;
    unsigned generation = 0;  // the slot is used when it equals the table's
    double value;
  };
  static std::size_t hash(const Key& k, int kind) {
    std::size_t h = std::hash<long>()(k.x * 1000003L + k.y);
    h ^= std::hash<long>()((static_cast<long>(k.shape) << 40) ^
                           (static_cast<long>(k.neighbour) << 8) ^ ((k.image_x + 2) << 4) ^
                           (k.image_y + 2) ^ (static_cast<long>(kind) << 60)) +
         0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h * 0x9e3779b97f4a7c15ULL;
  }
  template <class Measure>
  double lookup(const Key& key, int kind, Measure& measure) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = (hash(key, kind) >> 20) & mask;; i = (i + 1) & mask) {
      Slot& slot = slots_[i];
      if (slot.generation != generation_) {
        slot = {key, kind, generation_, measure()};
        ++size_;
        return slot.value;
      }
      if (slot.kind == kind && slot.key == key) return slot.value;
    }
  }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(std::max<std::size_t>(1024, 2 * old.size()), Slot{});
    const unsigned previous = generation_;
    ++generation_;  // every new slot is free (generation 0 is never current)
    size_ = 0;
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.generation != previous) continue;
      std::size_t i = (hash(slot.key, slot.kind) >> 20) & mask;
      while (slots_[i].generation == generation_) i = (i + 1) & mask;
      slots_[i] = slot;
      slots_[i].generation = generation_;
      ++size_;
    }
  }
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
  unsigned generation_ = 1;
};

}  // namespace shapeproc::fit
