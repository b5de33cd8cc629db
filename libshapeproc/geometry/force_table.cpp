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

// The angle between two non-zero vectors, robust near 0 and π.
double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

struct ForceTable::Shards {
  struct Shard {
    std::mutex mutex;
    std::unordered_map<Key, Vec3, KeyHash> forces;
  };
  std::array<Shard, kShards> shard;
};

ForceTable::ForceTable(int dimension, const DirectionBins& bins, std::size_t pairs,
                       std::size_t max_points, std::uint32_t open_after)
    : dimension_(dimension),
      bins_(bins),
      max_points_(max_points),
      open_after_(open_after),
      pair_queries_(std::make_unique<std::atomic<std::uint32_t>[]>(pairs)),
      pairs_(pairs),
      shards_(std::make_unique<Shards>()) {}

ForceTable::~ForceTable() = default;

std::optional<Vec3> ForceTable::point(std::size_t pair, const std::array<std::int32_t, 3>& index,
                                      double pitch,
                                      const std::function<Vec3(const Vec3&)>& exact) const {
  const Key key{pair, index};
  Shards::Shard& shard = shards_->shard[KeyHash{}(key) % kShards];
  {
    const std::lock_guard<std::mutex> lock(shard.mutex);
    const auto found = shard.forces.find(key);
    if (found != shard.forces.end()) return found->second;
  }
  // A full table computes no more points: the caller's one exact force is cheaper than a
  // cell's corners that would not be kept.
  if (held_.load(std::memory_order_relaxed) >= max_points_) return std::nullopt;
  const Vec3 offset(index[0] * pitch, index[1] * pitch, index[2] * pitch);
  const Vec3 force = exact(offset);
  const std::lock_guard<std::mutex> lock(shard.mutex);
  if (shard.forces.emplace(key, force).second) held_.fetch_add(1, std::memory_order_relaxed);
  return force;
}

std::optional<int> ForceTable::vouched_axis(const Vec3& estimate, double spread) const {
  const int axis = bins_.axis_of(estimate);
  if (bins_.directions() == 1) return axis;
  if (dimension_ == 2) {
    // Within half a direction sector, the two ends of the arc decide every direction on it.
    if (!(spread < core::kPi / bins_.directions())) return std::nullopt;
    const double angle = std::atan2(estimate.y(), estimate.x());
    for (const double end : {angle - spread, angle + spread}) {
      if (bins_.axis_of(Vec3(std::cos(end), std::sin(end), 0.0)) != axis) return std::nullopt;
    }
    return axis;
  }
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
  double spread = 0.0;
  for (int c = 0; c < corners; ++c)
    spread = std::max(spread, angle_between(force[static_cast<std::size_t>(c)], estimate));
  const std::optional<int> vouched = vouched_axis(estimate, 2.0 * spread + 1e-4);
  if (vouched) answered_.fetch_add(1, std::memory_order_relaxed);
  return vouched;
}

}  // namespace shapeproc::geometry
