#pragma once
// Seeded random numbers that give the same sequence on every platform and standard library
// (std::uniform_real_distribution is implementation-defined, so we derive values ourselves).
#include <cstdint>
#include <random>

namespace sc {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  std::uint64_t next_u64() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n) without modulo bias (n > 0).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t x;
    do x = engine_();
    while (x >= limit);
    return x % n;
  }
  // Standard normal (Box-Muller, no cached second value so state depends only on call count).
  double normal();
  // A child generator for an independent stream (e.g. one per scenario), stable under reordering.
  Rng fork(std::uint64_t stream) const;

 private:
  std::mt19937_64 engine_;
};

}  // namespace sc
