#include "engine/core/fixed_step_clock.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/error.hpp"

namespace sc {
namespace {

TEST(FixedStepClock, ExactFramesGiveOneStepEach) {
  FixedStepClock clock(1.0 / 60.0, 8);
  for (int i = 0; i < 600; ++i) {
    const ClockAdvance a = clock.advance(1.0 / 60.0);
    ASSERT_EQ(a.steps, 1) << "frame " << i;
    EXPECT_LT(a.alpha, 1e-6);
  }
}

TEST(FixedStepClock, FastDisplayInterpolatesBetweenSteps) {
  FixedStepClock clock(0.01, 8);
  ClockAdvance a = clock.advance(0.004);
  EXPECT_EQ(a.steps, 0);
  EXPECT_NEAR(a.alpha, 0.4, 1e-9);
  a = clock.advance(0.004);
  EXPECT_EQ(a.steps, 0);
  EXPECT_NEAR(a.alpha, 0.8, 1e-9);
  a = clock.advance(0.004);
  EXPECT_EQ(a.steps, 1);
  EXPECT_NEAR(a.alpha, 0.2, 1e-9);
}

TEST(FixedStepClock, SimulatedTimeTracksWallTimeOverManyIrregularFrames) {
  FixedStepClock clock(1.0 / 120.0, 8);
  long steps = 0;
  double wall = 0;
  for (int i = 0; i < 10000; ++i) {
    const double dt = 0.004 + 0.003 * std::sin(i * 0.7);
    wall += dt;
    steps += clock.advance(dt).steps;
  }
  EXPECT_NEAR(static_cast<double>(steps) / 120.0 + clock.pending_seconds(), wall, 1e-9);
}

TEST(FixedStepClock, LongFrameIsClampedNoSpiralOfDeath) {
  FixedStepClock clock(1.0 / 60.0, 5);
  const ClockAdvance a = clock.advance(10.0);  // window was minimised for 10 s
  EXPECT_EQ(a.steps, 5);
  EXPECT_GT(a.dropped_seconds, 9.0);
  EXPECT_LT(clock.pending_seconds(), 1.0 / 60.0);
  EXPECT_GE(a.alpha, 0.0);
  EXPECT_LT(a.alpha, 1.0);
  EXPECT_EQ(clock.advance(1.0 / 60.0).steps, 1);  // and it recovers at once
}

TEST(FixedStepClock, BadElapsedTimesCountAsZero) {
  FixedStepClock clock(0.01, 4);
  EXPECT_EQ(clock.advance(-1).steps, 0);
  EXPECT_EQ(clock.advance(std::numeric_limits<double>::quiet_NaN()).steps, 0);
  EXPECT_EQ(clock.advance(std::numeric_limits<double>::infinity()).steps, 0);
  EXPECT_EQ(clock.pending_seconds(), 0.0);
}

TEST(FixedStepClock, RejectsBadConfiguration) {
  EXPECT_THROW(FixedStepClock(0, 4), InputError);
  EXPECT_THROW(FixedStepClock(0.01, 0), InputError);
}

}  // namespace
}  // namespace sc
