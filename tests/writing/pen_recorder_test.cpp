#include "engine/writing/pen_recorder.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace sc::writing {
namespace {

TEST(PenRecorder, PressMoveReleaseEndsAClassicTrial) {
  PenRecorder rec(10.0, {true, 30.0});
  rec.add({10.1, 5, 5, false});   // hover: not recorded
  rec.add({10.2, 5, 150, true});  // press
  rec.add({10.3, 5, 150, true});  // a frame without motion: nothing new
  rec.add({10.35, 9, 150, true});
  rec.add({10.4, 9, 146, false});  // release at a new position
  EXPECT_TRUE(rec.ended());
  EXPECT_EQ(rec.end_reason(), TrialEnd::Released);
  const auto& raw = rec.raw();
  ASSERT_EQ(raw.points.size(), 3u);
  EXPECT_EQ(raw.points[0], (TracePoint{5, 150, false}));
  EXPECT_EQ(raw.points[1], (TracePoint{9, 150, true}));
  EXPECT_EQ(raw.points[2], (TracePoint{9, 146, true}));
  EXPECT_NEAR(raw.times[0], 0.2, 1e-12);
  EXPECT_NEAR(raw.times[2], 0.4, 1e-12);
  rec.add({10.5, 20, 20, true});  // after the end: ignored
  EXPECT_EQ(rec.raw().points.size(), 3u);
  // Infilled with the reference rule: 4 px -> 1 px steps, times interpolated.
  const auto filled = rec.infilled();
  ASSERT_EQ(filled.points.size(), 9u);
  EXPECT_EQ(filled.points[2], (TracePoint{7, 150, true}));
  EXPECT_NEAR(filled.times[2], 0.275, 1e-12);  // halfway between the press (0.2) and 0.35
  for (std::size_t i = 1; i < filled.points.size(); ++i) {
    EXPECT_LE(std::fabs(filled.points[i].x - filled.points[i - 1].x), 1.0);
    EXPECT_LE(std::fabs(filled.points[i].y - filled.points[i - 1].y), 1.0);
  }
}

TEST(PenRecorder, MultiStrokeTrialNeedsDoneAndRecordsPenUpMoves) {
  PenRecorder rec(0.0, {false, 30.0});
  rec.add({0.1, 0, 0, true});
  rec.add({0.2, 3, 0, true});
  rec.add({0.3, 3, 0, false});  // release where the pen already is: nothing new
  EXPECT_FALSE(rec.ended());
  rec.add({0.4, 20, 20, false});  // hovering to the next stroke
  rec.add({0.5, 20, 20, true});   // a tap ...
  rec.add({0.6, 20, 20, false});  // ... leaves a dot
  rec.done(0.7);
  EXPECT_EQ(rec.end_reason(), TrialEnd::Done);
  const auto& p = rec.raw().points;
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[2], (TracePoint{20, 20, false}));  // pen-up move to the tap
  EXPECT_EQ(p[3], (TracePoint{20, 20, true}));   // the dot
}

TEST(PenRecorder, TimeLimitEndsTheTrial) {
  PenRecorder rec(0.0, {true, 2.0});
  rec.add({0.5, 1, 1, true});
  rec.add({1.0, 2, 1, true});
  EXPECT_NEAR(rec.seconds_left(1.0), 1.0, 1e-12);
  rec.tick(2.5);
  EXPECT_EQ(rec.end_reason(), TrialEnd::TimeLimit);
  EXPECT_FALSE(rec.pressed());
  rec.add({2.6, 3, 1, false});  // the release comes too late to count
  EXPECT_EQ(rec.raw().points.size(), 2u);
  EXPECT_EQ(rec.seconds_left(3.0), 0.0);
}

TEST(PenRecorder, RulesFollowTheScenario) {
  const auto classic = gold_trajectory({"b-a-t-^-", AlphabetKind::Classic, {}});
  const auto rules = pen_rules_for(classic);
  EXPECT_TRUE(rules.end_on_release);
  EXPECT_DOUBLE_EQ(rules.time_limit_seconds, kTimeLimitSecondsPerStep * static_cast<double>(classic.steps.size()));
  EXPECT_FALSE(pen_rules_for(gold_trajectory({"B-P", AlphabetKind::Balinese, {}})).end_on_release);
  EXPECT_EQ(writing_time_limit_seconds(10), kMinTimeLimitSeconds);
  EXPECT_DOUBLE_EQ(writing_time_limit_seconds(2000), 30.0);  // proportional to the word's length
}

}  // namespace
}  // namespace sc::writing
