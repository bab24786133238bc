// Determinism pinned across machines, as Box2D pins EXPECTED_HASH: the exact bits of a parking episode,
// of an expert plan and of a CompILE segmentation of a fixed trial, hashed (FNV-1a, 64 bit) and compared
// with the values below. Same seed, same result on any machine: a change that moves one of these changes
// what learners, instructors and researchers get. docs/development.md ("Determinism hashes") says which
// changes may move them and how to re-pin.
#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/asset_paths.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking/parking_sim.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

struct Fnv1a {
  std::uint64_t value = 0xcbf29ce484222325ULL;
  void bytes(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      value ^= (v >> (8 * i)) & 0xffU;
      value *= 0x100000001b3ULL;
    }
  }
  void add(double v) { bytes(std::bit_cast<std::uint64_t>(v)); }
  void add(int v) { bytes(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))); }
};

std::string hex(std::uint64_t v) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(v));
  return text;
}

// The 100-step episode of a fixed scenario driven by seeded actions (no early stop: every state counts).
std::uint64_t parking_episode_hash() {
  Rng rng(2026);
  const ParkingScenario scenario = parking_pool_scenario(0, 7);
  ParkingSim sim(scenario);
  Fnv1a h;
  for (int t = 0; t < 100 && !sim.done(); ++t) {
    const ParkingStepResult r = sim.step({rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)});
    for (double v : sim.observation()) h.add(v);
    h.add(r.reward);
  }
  return h.value;
}

std::uint64_t expert_plan_hash() {
  const ParkingPlan plan = ParkingExpert().plan(parking_pool_scenario(0, 3));
  Fnv1a h;
  for (const ParkingAction& a : plan.actions) {
    h.add(a[0]);
    h.add(a[1]);
  }
  h.add(plan.success_step);
  return h.value;
}

std::uint64_t compile_segmentation_hash() {
  const CompileExtractor extractor = CompileExtractor::load(asset_dir() / "models" / "parking.pt", "parking");
  Fnv1a h;
  for (int index : {3, 11, 42}) {
    const ParkingScenario scenario = parking_pool_scenario(0, index);
    const Segmentation s = extractor.extract(parking_step_sequence(ParkingExpert().plan(scenario).to_trial(scenario)));
    for (const SkillSegment& segment : s.segments) {
      h.add(segment.skill);
      h.add(segment.begin);
      h.add(segment.end);
    }
  }
  return h.value;
}

TEST(DeterminismHash, ParkingEpisode) { EXPECT_EQ(hex(parking_episode_hash()), "0xf7fcd1c8f3eaeeef"); }
TEST(DeterminismHash, ExpertPlan) { EXPECT_EQ(hex(expert_plan_hash()), "0xa7864a532b9bec99"); }
TEST(DeterminismHash, CompileSegmentationOfFixedTrials) {
  EXPECT_EQ(hex(compile_segmentation_hash()), "0xe87002318e7a04d6");
}

}  // namespace
}  // namespace sc
