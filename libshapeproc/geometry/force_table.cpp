#include "libshapeproc/geometry/force_table.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <unordered_map>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::geometry {
namespace {

struct Key {
  std::size_t pair;
  std::array<std::int32_t, 3> index;
  bool operator==(const Key& other) const { return pair == other.pair && index == other.index; }
};

struct KeyHash {
  std::size_t operator()(const Key& key) const {
    // A multiply–xorshift mix of the four words (the grid's neighbours differ in low bits).
    std::uint64_t h = static_cast<std::uint64_t>(key.pair) * 0x9E3779B97F4A7C15ULL;
    for (const std::int32_t i : key.index) {
      h ^= static_cast<std::uint32_t>(i) + 0x7F4A7C159E3779B9ULL + (h << 6) + (h >> 2);
      h *= 0xBF58476D1CE4E5B9ULL;
    }
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

constexpr std::size_t kShards = 64;
constexpr std::size_t kRecentBlocks = 8;  // per thread

// A point's state: not computed, claimed by the thread computing it, or ready to read.
enum : std::uint8_t { kEmpty = 0, kClaimed = 1, kReady = 2 };

// ⌊a / b⌋ for b > 0, also for negative a.
std::int32_t floor_div(std::int32_t a, std::int32_t b) {
  return a >= 0 ? a / b : -((-a - 1) / b) - 1;
}

std::atomic<std::uint64_t> next_table_id{1};

}  // namespace

struct ForceTable::Block {
  explicit Block(std::size_t slots)
      : state(std::make_unique<std::atomic<std::uint8_t>[]>(slots)),
        force(std::make_unique<Vec3[]>(slots)) {
    for (std::size_t i = 0; i < slots; ++i) state[i].store(kEmpty, std::memory_order_relaxed);
  }
  std::unique_ptr<std::atomic<std::uint8_t>[]> state;
  std::unique_ptr<Vec3[]> force;
};

struct ForceTable::Shards {
  struct Shard {
    std::mutex mutex;
    std::unordered_map<Key, std::unique_ptr<Block>, KeyHash> blocks;
  };
  std::array<Shard, kShards> shard;
};

namespace {

// The blocks a thread used last, by table, pair and block index. Tables have unique ids and
// blocks live as long as their table, so an entry of a table that is gone is never matched.
struct RecentBlock {
  std::uint64_t table = 0;
  std::size_t pair = 0;
  std::array<std::int32_t, 3> block{};
  void* at = nullptr;
};
thread_local std::array<RecentBlock, kRecentBlocks> recent_blocks;

}  // namespace

ForceTable::ForceTable(int dimension, const DirectionBins& bins, std::size_t pairs,
                       std::size_t max_points, std::uint32_t open_after)
    : dimension_(dimension),
      side_(dimension == 2 ? 16 : 8),
      block_slots_(dimension == 2 ? 16 * 16 : 8 * 8 * 8),
      id_(next_table_id.fetch_add(1, std::memory_order_relaxed)),
      bins_(bins),
      max_points_(max_points),
      open_after_(open_after),
      pair_queries_(std::make_unique<std::atomic<std::uint32_t>[]>(pairs)),
      pairs_(pairs),
      shards_(std::make_unique<Shards>()) {}

ForceTable::~ForceTable() = default;

ForceTable::Block* ForceTable::block_of(std::size_t pair, const std::array<std::int32_t, 3>& index,
                                        std::size_t& slot) const {
  Key key{pair, {0, 0, 0}};
  slot = 0;
  for (int d = dimension_ - 1; d >= 0; --d) {
    const std::size_t i = static_cast<std::size_t>(d);
    key.index[i] = floor_div(index[i], side_);
    slot = slot * static_cast<std::size_t>(side_) +
           static_cast<std::size_t>(index[i] - key.index[i] * side_);
  }
  const std::size_t hash = KeyHash{}(key);
  RecentBlock& recent = recent_blocks[hash % kRecentBlocks];
  if (recent.table == id_ && recent.pair == pair && recent.block == key.index)
    return static_cast<Block*>(recent.at);
  Shards::Shard& shard = shards_->shard[(hash / kRecentBlocks) % kShards];
  const std::lock_guard<std::mutex> lock(shard.mutex);
  auto found = shard.blocks.find(key);
  if (found == shard.blocks.end()) {
    // A full table allocates no more blocks (a query needing one falls back to the caller).
    if (held_.load(std::memory_order_relaxed) >= max_points_ ||
        slots_.load(std::memory_order_relaxed) >= kSlotsPerPoint * max_points_)
      return nullptr;
    found = shard.blocks.emplace(key, std::make_unique<Block>(block_slots_)).first;
    slots_.fetch_add(block_slots_, std::memory_order_relaxed);
  }
  recent = {id_, pair, key.index, found->second.get()};
  return found->second.get();
}

std::optional<Vec3> ForceTable::point(std::size_t pair, const std::array<std::int32_t, 3>& index,
                                      double pitch,
                                      const std::function<Vec3(const Vec3&)>& exact) const {
  std::size_t slot = 0;
  Block* block = block_of(pair, index, slot);
  if (block && block->state[slot].load(std::memory_order_acquire) == kReady)
    return block->force[slot];
  // A full table computes no more points: the caller's one exact force is cheaper than a
  // cell's corners that would not be kept.
  if (!block || held_.load(std::memory_order_relaxed) >= max_points_) return std::nullopt;
  const Vec3 offset(index[0] * pitch, index[1] * pitch, index[2] * pitch);
  const Vec3 force = exact(offset);
  // Another thread computing the same point keeps its own: both are the same exact value.
  std::uint8_t empty = kEmpty;
  if (block->state[slot].compare_exchange_strong(empty, kClaimed, std::memory_order_acq_rel)) {
    block->force[slot] = force;
    block->state[slot].store(kReady, std::memory_order_release);
    held_.fetch_add(1, std::memory_order_relaxed);
  }
  return force;
}

std::optional<int> ForceTable::vouched_axis(const Vec3& estimate, double spread) const {
  if (bins_.directions() == 1) return bins_.axis_of(estimate);
  if (dimension_ == 2) return bins_.arc_axis(estimate, spread);
  const int axis = bins_.axis_of(estimate);
  // 3D: a narrow cone about the estimate, sampled on its rim (HEALPix base pixels are wide and
  // their edges gently curved at this scale).
  constexpr double kWidestCone = 0.25;
  if (!(spread < kWidestCone)) return std::nullopt;
  const Vec3 e = estimate.normalized();
  const Vec3 u = e.unitOrthogonal(), v = e.cross(u);
  constexpr int kRim = 16;
  for (int k = 0; k < kRim; ++k) {
    const double phi = 2 * core::kPi * k / kRim;
    const Vec3 rim =
        std::cos(spread) * e + std::sin(spread) * (std::cos(phi) * u + std::sin(phi) * v);
    if (bins_.axis_of(rim) != axis) return std::nullopt;
  }
  return axis;
}

std::optional<int> ForceTable::axis(std::size_t pair, double pitch, const Vec3& offset,
                                    double negligible,
                                    const std::function<Vec3(const Vec3&)>& exact) const {
  queries_.fetch_add(1, std::memory_order_relaxed);
  if (pair >= pairs_ || !(pitch > 0)) return std::nullopt;
  std::atomic<std::uint32_t>& asked = pair_queries_[pair];
  if (asked.load(std::memory_order_relaxed) < open_after_) {
    asked.fetch_add(1, std::memory_order_relaxed);
    return std::nullopt;
  }
  const int dims = dimension_;
  std::array<std::int32_t, 3> base{0, 0, 0};
  std::array<double, 3> fraction{0.0, 0.0, 0.0};
  for (int d = 0; d < dims; ++d) {
    const double u = offset[d] / pitch;
    if (!(std::abs(u) < 1e9)) return std::nullopt;  // off any grid the table can index
    const double cell = std::floor(u);
    base[static_cast<std::size_t>(d)] = static_cast<std::int32_t>(cell);
    fraction[static_cast<std::size_t>(d)] = u - cell;
  }
  const int corners = 1 << dims;
  std::array<Vec3, 8> force;
  Vec3 estimate = Vec3::Zero();
  for (int c = 0; c < corners; ++c) {
    std::array<std::int32_t, 3> index = base;
    double weight = 1.0;
    for (int d = 0; d < dims; ++d) {
      const bool up = (c >> d) & 1;
      index[static_cast<std::size_t>(d)] += up ? 1 : 0;
      const double f = fraction[static_cast<std::size_t>(d)];
      weight *= up ? f : 1.0 - f;
    }
    const std::optional<Vec3> at = point(pair, index, pitch, exact);
    if (!at || !(at->norm() > negligible)) return std::nullopt;
    force[static_cast<std::size_t>(c)] = *at;
    estimate += weight * force[static_cast<std::size_t>(c)];
  }
  if (!(estimate.norm() > negligible)) return std::nullopt;
  // The corners' widest angle about the estimate, from the largest tangent: a corner a right
  // angle or more away spreads too far to vouch for any axis.
  double widest = 0.0;
  for (int c = 0; c < corners; ++c) {
    const Vec3& f = force[static_cast<std::size_t>(c)];
    const double along = f.dot(estimate);
    if (!(along > 0)) return std::nullopt;
    widest = std::max(widest, f.cross(estimate).norm() / along);
  }
  const double spread = std::atan(widest);
  const std::optional<int> vouched = vouched_axis(estimate, 2.0 * spread + 5e-3);
  if (vouched) answered_.fetch_add(1, std::memory_order_relaxed);
  return vouched;
}

}  // namespace shapeproc::geometry
