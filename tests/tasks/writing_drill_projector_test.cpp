#include "teaching/tasks/writing_drill_projector.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/writing_kit.hpp"

namespace sc {
namespace {

const WritingKit& writing_projector_kit() {
  static const WritingKit k(std::make_shared<TimeHeuristicExtractor>(8), "",
                            WritingKitOptions{{}, writing::AlphabetKind::Classic, 5, 9, std::nullopt});
  return k;
}

DrillSegment writing_slice(int e, int k) {
  const SkillSegment s = writing_projector_kit()
                             .expert_pool()[static_cast<std::size_t>(e)]
                             .time_slices.segments[static_cast<std::size_t>(k)];
  return {s.skill, e, s.begin, s.end};
}

DrillPlan writing_plan_of(std::vector<DrillSegment> segments, int repetitions = 1) {
  DrillPlan p;
  for (const auto& s : segments) p.ngram.push_back(s.skill);
  std::vector<DrillSegment> all;
  for (int r = 0; r < repetitions; ++r) all.insert(all.end(), segments.begin(), segments.end());
  p.segments = std::move(all);
  p.repetitions = repetitions;
  return p;
}

TEST(WritingDrillProjector, SegmentsAreChainedWithoutJumpsAndKeepTheirMoves) {
  const DrillPlan plan = writing_plan_of({writing_slice(0, 2), writing_slice(3, 5)}, 3);
  const PlayableDrill d = writing_projector_kit().projector().project(plan);
  ASSERT_EQ(d.steps.length(), plan.length());
  ASSERT_EQ(d.ghost_path.size(), static_cast<std::size_t>(plan.length()) + 1);
  // Every ghost step is exactly the expert's pen move (1-px steps after infill): no jump anywhere.
  for (int t = 0; t < d.steps.length(); ++t) {
    const double dx = d.ghost_path[t + 1][0] - d.ghost_path[t][0];
    const double dy = d.ghost_path[t + 1][1] - d.ghost_path[t][1];
    EXPECT_NEAR(dx, d.steps.actions[2 * t], 1e-4);
    EXPECT_NEAR(dy, d.steps.actions[2 * t + 1], 1e-4);
    EXPECT_LE(std::hypot(dx, dy), 1.5) << "step " << t;
    EXPECT_FLOAT_EQ(d.steps.states[t * d.steps.state_dim], static_cast<float>(d.ghost_path[t][0]));
  }
  for (const auto& p : d.ghost_path) {
    EXPECT_GE(p[0], 0.0);
    EXPECT_LE(p[0], writing::kCanvasWidth);
    EXPECT_GE(p[1], 0.0);
    EXPECT_LE(p[1], writing::kCanvasHeight);
  }
  EXPECT_EQ(d.segment_starts, plan.segment_starts());
}

TEST(WritingDrillProjector, DrillStartsWhereItsFirstSegmentStartsWhenThatFits) {
  const DrillPlan plan = writing_plan_of({writing_slice(1, 0), writing_slice(2, 1)});
  const PlayableDrill d = writing_projector_kit().projector().project(plan);
  const StepSequence& e = writing_projector_kit().expert_pool()[1].steps;
  EXPECT_NEAR(d.ghost_path[0][0], e.states[0], 1e-6);  // slice 0 starts at the word's start (0, 150)
  EXPECT_NEAR(d.ghost_path[0][1], e.states[1], 1e-6);
}

TEST(WritingDrillProjector, PathLeavingTheCanvasIsShiftedInsideAndPenFlagsAreKept) {
  // A synthetic 3-D (dx, dy, pen) expert: 40 px right with the pen down, 20 px up lifted, 40 px right.
  StepSequence e;
  e.state_dim = 3;
  e.action_dim = 3;
  for (int t = 0; t < 100; ++t) {
    const bool lifted = t >= 40 && t < 60;
    e.states.insert(e.states.end(), {480.0f + (t < 40   ? t
                                               : t < 60 ? 40.0f
                                                        : t - 20.0f),
                                     t < 40 ? 5.0f : 5.0f - (std::min(t, 60) - 40), static_cast<float>(t)});
    e.actions.insert(e.actions.end(), {lifted ? 0.0f : 1.0f, lifted ? -1.0f : 0.0f, lifted ? 0.0f : 1.0f});
  }
  const WritingDrillProjector projector({e});
  DrillPlan plan = writing_plan_of({{0, 0, 0, 100}});
  const PlayableDrill d = projector.project(plan);
  double max_x = 0, min_y = 1e9;
  for (const auto& p : d.ghost_path) {
    max_x = std::max(max_x, p[0]);
    min_y = std::min(min_y, p[1]);
  }
  EXPECT_DOUBLE_EQ(max_x, writing::kCanvasWidth);  // 480 + 80 = 560 -> shifted left by 60
  EXPECT_DOUBLE_EQ(min_y, 0.0);                    // 5 - 20 = -15 -> shifted down by 15
  const auto trace = WritingDrillProjector::drill_trace(d);
  ASSERT_EQ(trace.size(), 101u);
  EXPECT_TRUE(trace[40].pen);
  EXPECT_FALSE(trace[41].pen);
  EXPECT_FALSE(trace[60].pen);
  EXPECT_TRUE(trace[61].pen);
}

TEST(WritingDrillProjector, DrillTrialIsAPlayableWritingTrialOfTheGhost) {
  const PlayableDrill d =
      writing_projector_kit().projector().project(writing_plan_of({writing_slice(0, 3), writing_slice(4, 4)}, 3));
  const Json doc = writing_projector_kit().drill_trial(d);
  const writing::WritingTrial trial = writing::parse_writing_trial(doc, "drill");
  EXPECT_EQ(trial.source, "drill");
  EXPECT_FALSE(trial.scenario.word.empty());
  ASSERT_EQ(trial.points.size(), d.ghost_path.size());
  EXPECT_DOUBLE_EQ(trial.points.back().x, d.ghost_path.back()[0]);
  EXPECT_NEAR(writing_projector_kit().drill_attempt_reward(d, doc), 0.0, 1e-12);
  writing::WritingTrial shifted = trial;
  for (auto& p : shifted.points) p.y += 30.0;
  EXPECT_LT(writing_projector_kit().drill_attempt_reward(d, writing::writing_trial_json(shifted)), -0.9);
}

TEST(WritingDrillProjector, BadPlansAreInputErrors) {
  EXPECT_THROW(writing_projector_kit().projector().project(DrillPlan{}), InputError);
  EXPECT_THROW(writing_projector_kit().projector().project(writing_plan_of({{0, 7, 0, 2}})), InputError);
}

}  // namespace
}  // namespace sc
