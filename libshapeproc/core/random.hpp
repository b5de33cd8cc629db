// The random generator every sampler takes explicitly: 64-bit Mersenne Twister with its own
// conversions to uniform doubles and indices, so that the same seed gives the same draws with any
// standard library (std::uniform_*_distribution is implementation-defined).
#pragma once

#include <cstdint>
#include <random>

namespace shapeproc::core {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * (1.0 / 9007199254740992.0); }
  // Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Uniform index in [0, n), n > 0, without modulo bias (rejection).
  std::uint64_t index(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t x;
    do {
      x = engine_();
    } while (x >= limit);
    return x % n;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace shapeproc::core
