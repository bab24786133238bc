#pragma once
// The seeds of a synthetic-student experiment, parking and writing alike. Every use draws from its own stream
// of Rng::fork, so adding a use or reordering them leaves the other uses' draws, and so the published tables,
// unchanged.
#include <cstdint>

#include "engine/core/rng.hpp"

namespace sc::experiment_seeds {

enum Stream : std::uint64_t {
  kStudentInit = 1,
  kEvaluationSet = 2,
  kFinetuneData = 3,
  kFinetuneTraining = 4,
  kRehearsal = 5,
  kStudentDrives = 6,  // parking only
  kHeldoutDrives = 7,  // parking only
  kCurve = 8,          // parking only
};

// The seed of use (stream, a, b) in the experiment of `seed`.
inline std::uint64_t derived_seed(std::uint64_t seed, Stream stream, std::uint64_t a = 0, std::uint64_t b = 0) {
  return Rng(seed).fork(stream).fork(a).fork(b).next_u64();
}

}  // namespace sc::experiment_seeds
