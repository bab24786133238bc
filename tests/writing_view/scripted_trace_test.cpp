#include "engine/writing_view/scripted_trace.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/writing/writing_scenario.hpp"
#include "engine/writing/writing_score.hpp"

namespace sc::writing_view {
namespace {

using writing::TracePoint;

TEST(ScriptedTrace, IsDeterministicWobblyAndKeepsPenLifts) {
  const auto gold = writing::gold_trajectory({"P-T", writing::AlphabetKind::Balinese, {}}).points();
  const ScriptedHand hand{5, 2.5, 4, 1.0};
  const auto a = scripted_learner_trace(gold, hand);
  EXPECT_EQ(a, scripted_learner_trace(gold, hand));
  EXPECT_NE(a, scripted_learner_trace(gold, {6, 2.5, 4, 1.0}));
  EXPECT_LT(a.size(), gold.size() / 3);
  int gold_lifts = 0, trace_lifts = 0;
  for (std::size_t i = 1; i < gold.size(); ++i) gold_lifts += gold[i].pen && !gold[i - 1].pen;
  for (std::size_t i = 1; i < a.size(); ++i) trace_lifts += a[i].pen && !a[i - 1].pen;
  EXPECT_GT(gold_lifts, 0);
  EXPECT_EQ(trace_lifts, gold_lifts);
  // Every point lies within the wobble of the gold path, and the wobble is visible.
  double max_offset = 0;
  for (const TracePoint& p : a) {
    double nearest = 1e9;
    for (const TracePoint& g : gold) nearest = std::min(nearest, std::hypot(p.x - g.x, p.y - g.y));
    max_offset = std::max(max_offset, nearest);
  }
  EXPECT_GT(max_offset, 1.0);
  EXPECT_LE(max_offset, 2.5 * std::sqrt(2.0) + 1e-9);
}

TEST(ScriptedTrace, SmallWobbleScoresHighAndHalfAWordAboutHalf) {
  const auto gold = writing::gold_trajectory({"ab-c", writing::AlphabetKind::Classic, {}}).points();
  const double full = writing::score_writing(gold, scripted_learner_trace(gold, {3, 1.5, 4, 1.0})).score;
  const double half = writing::score_writing(gold, scripted_learner_trace(gold, {3, 1.5, 4, 0.5})).score;
  EXPECT_GT(full, -0.05);
  EXPECT_NEAR(half, -0.5, 0.1);
  EXPECT_TRUE(scripted_learner_trace({}, {}).empty());
}

}  // namespace
}  // namespace sc::writing_view
