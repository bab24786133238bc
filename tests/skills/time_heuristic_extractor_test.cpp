#include "teaching/skills/time_heuristic_extractor.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

StepSequence steps(int t) {
  StepSequence s;
  s.action_dim = 2;
  s.actions.assign(static_cast<std::size_t>(2 * t), 0.0f);
  return s;
}

TEST(TimeHeuristicExtractor, SplitsIntoEqualForwardSlices) {
  TimeHeuristicExtractor ex(3);
  Segmentation seg = ex.extract(steps(18));
  ASSERT_EQ(seg.segments.size(), 3u);
  EXPECT_EQ(seg.segments[0], (SkillSegment{0, 0, 6}));
  EXPECT_EQ(seg.segments[1], (SkillSegment{1, 6, 12}));
  EXPECT_EQ(seg.segments[2], (SkillSegment{2, 12, 18}));
}

TEST(TimeHeuristicExtractor, CoversEveryStepWhenNotDivisible) {
  TimeHeuristicExtractor ex(4);
  Segmentation seg = ex.extract(steps(19));
  int covered = 0, expect_begin = 0;
  for (const auto& s : seg.segments) {
    EXPECT_EQ(s.begin, expect_begin);
    EXPECT_GE(s.length(), 4);
    EXPECT_LE(s.length(), 5);
    covered += s.length();
    expect_begin = s.end;
  }
  EXPECT_EQ(covered, 19);
}

TEST(TimeHeuristicExtractor, ShorterThanKKeepsOneStepSlices) {
  // The reference crashed here (s = floor(T/K) = 0).
  TimeHeuristicExtractor ex(8);
  Segmentation seg = ex.extract(steps(3));
  ASSERT_EQ(seg.segments.size(), 3u);
  for (const auto& s : seg.segments) EXPECT_EQ(s.length(), 1);
  EXPECT_EQ(seg.segments.back().end, 3);
}

}  // namespace
}  // namespace sc
