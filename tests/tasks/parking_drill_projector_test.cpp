#include "teaching/tasks/parking_drill_projector.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/parking/parking_expert.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

const ParkingKit& projector_kit() {
  static const ParkingKit k(std::make_shared<TimeHeuristicExtractor>(3), "",
                            ParkingKitOptions{{}, ParkingPoolOptions{6, 21}, std::nullopt});
  return k;
}

ParkingTrial expert(int i) {
  return parse_parking_trial(projector_kit().expert_pool()[static_cast<std::size_t>(i)].trial, "pool");
}

// Slice k (of the time heuristic's 3) of expert e as a drill segment.
DrillSegment slice(int e, int k) {
  const SkillSegment s =
      projector_kit().expert_pool()[static_cast<std::size_t>(e)].time_slices.segments[static_cast<std::size_t>(k)];
  return {s.skill, e, s.begin, s.end};
}

DrillPlan plan_of(std::vector<DrillSegment> segments) {
  DrillPlan p;
  for (const auto& s : segments) p.ngram.push_back(s.skill);
  p.segments = std::move(segments);
  return p;
}

TEST(ParkingDrillProjector, WholeExpertTrajectoryReproducesTheExpert) {
  const ParkingTrial e = expert(2);
  const int t = static_cast<int>(e.actions.size());
  const PlayableDrill d = projector_kit().projector().project(plan_of({{0, 2, 0, t}}));
  ASSERT_EQ(d.steps.length(), t);
  ASSERT_EQ(d.ghost_path.size(), e.states.size());
  for (std::size_t i = 0; i < e.states.size(); ++i) {
    EXPECT_NEAR(d.ghost_path[i][0], e.states[i][0] * 100, 1e-9);
    EXPECT_NEAR(d.ghost_path[i][1], e.states[i][1] * 100, 1e-9);
  }
  EXPECT_TRUE(d.success);
  EXPECT_NEAR(d.drill_return, e.rewards.back(), 1e-12);
}

TEST(ParkingDrillProjector, StitchedDrillStartsAtTheFirstSegmentAndReplaysToItsGhost) {
  const DrillPlan plan = plan_of({slice(0, 1), slice(3, 2), slice(4, 0)});
  const PlayableDrill d = projector_kit().projector().project(plan);
  // Initial state: the first segment's expert state (position in metres).
  // A copy: expert() returns a temporary (a reference into it dangled; found by AddressSanitizer).
  const ParkingObservation s0 = expert(0).states[static_cast<std::size_t>(plan.segments[0].begin)];
  EXPECT_NEAR(d.ghost_path[0][0], s0[0] * 100, 1e-9);
  EXPECT_NEAR(d.ghost_path[0][1], s0[1] * 100, 1e-9);
  ASSERT_GE(d.steps.length(), 1);
  EXPECT_LE(d.steps.length(), plan.length());
  EXPECT_EQ(d.ghost_path.size(), static_cast<std::size_t>(d.steps.length()) + 1);
  // No jumps: with the acceleration held for a control step the speed is monotonic inside it, so the car
  // moves at most 0.2 s x the larger |speed| at the step's two ends.
  for (std::size_t i = 1; i < d.ghost_path.size(); ++i) {
    auto speed = [&](std::size_t k) {
      const float* o = d.steps.states.data();  // T rows; the state after the last action is final_state
      const std::vector<float> row = k < static_cast<std::size_t>(d.steps.length())
                                         ? std::vector<float>(o + k * 12, o + k * 12 + 12)
                                         : d.final_state;
      return 5.0 * std::hypot(row[2], row[3]);
    };
    const double step =
        std::hypot(d.ghost_path[i][0] - d.ghost_path[i - 1][0], d.ghost_path[i][1] - d.ghost_path[i - 1][1]);
    EXPECT_LE(step, 0.2 * std::max(speed(i - 1), speed(i)) + 1e-3) << "step " << i;
  }
  // The drill trial, replayed in a fresh ParkingSim, gives exactly the ghost states and the drill's score.
  const ParkingTrial trial = parse_parking_trial(projector_kit().drill_trial(d), "drill");
  ASSERT_TRUE(trial.scenario.start.has_value());
  EXPECT_EQ(trial.source, "drill");
  EXPECT_EQ(trial.scenario.goal_spot, expert(4).scenario.goal_spot);  // the last segment's goal
  const ParkingPlan replay = simulate_plan(trial.scenario, trial.actions);
  ASSERT_EQ(replay.states.size(), d.ghost_path.size());
  for (std::size_t i = 0; i < replay.states.size(); ++i) {
    EXPECT_DOUBLE_EQ(replay.states[i][0] * 100, d.ghost_path[i][0]);
    EXPECT_DOUBLE_EQ(replay.states[i][1] * 100, d.ghost_path[i][1]);
  }
  EXPECT_DOUBLE_EQ(replay.rewards.back(), d.drill_return);
  EXPECT_EQ(replay.success, d.success);
  EXPECT_DOUBLE_EQ(projector_kit().drill_attempt_reward(d, projector_kit().drill_trial(d)), d.drill_return);
  // Segment starts are the plan's prefix sums (clipped when the car parked early).
  ASSERT_EQ(d.segment_starts.size(), 3u);
  EXPECT_EQ(d.segment_starts[0], 0);
  EXPECT_EQ(d.segment_starts[1], std::min(plan.segments[0].length(), d.steps.length()));
}

TEST(ParkingDrillProjector, SameSegmentsSameDrill) {
  const DrillPlan plan = plan_of({slice(1, 0), slice(5, 1)});
  const PlayableDrill a = projector_kit().projector().project(plan);
  const PlayableDrill b = projector_kit().projector().project(plan);
  EXPECT_EQ(a.ghost_path, b.ghost_path);
  EXPECT_EQ(a.steps.states, b.steps.states);
  EXPECT_EQ(a.drill_return, b.drill_return);
}

TEST(ParkingDrillProjector, AttemptInAnotherScenarioIsRejected) {
  const PlayableDrill d = projector_kit().projector().project(plan_of({slice(1, 0), slice(2, 1)}));
  EXPECT_THROW(projector_kit().drill_attempt_reward(d, projector_kit().expert_pool()[0].trial), InputError);
}

TEST(ParkingDrillProjector, BadPlansAreInputErrors) {
  EXPECT_THROW(projector_kit().projector().project(DrillPlan{}), InputError);
  EXPECT_THROW(projector_kit().projector().project(plan_of({{0, 9, 0, 2}})), InputError);
  EXPECT_THROW(projector_kit().projector().project(plan_of({{0, 0, 0, 500}})), InputError);
}

}  // namespace
}  // namespace sc
