#include "engine/core/rng.hpp"

#include <cmath>
#include <numbers>

namespace sc {

double Rng::normal() {
  double u1 = uniform();
  double u2 = uniform();
  if (u1 < 1e-300) u1 = 1e-300;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Rng Rng::fork(std::uint64_t stream) const {
  // SplitMix64 of (first output of a copy, stream) decorrelates neighbouring streams.
  std::mt19937_64 copy = engine_;
  std::uint64_t z = copy() ^ (stream + 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return Rng(z ^ (z >> 31));
}

}  // namespace sc
