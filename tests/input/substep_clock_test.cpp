#include "engine/input/substep_clock.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc::input {
namespace {

TEST(SubstepClock, FifteenSubstepsPerSecondWhateverTheFrameRate) {
  for (double fps : {30.0, 60.0, 144.0}) {
    SubstepClock clock;
    int total = 0;
    const int frames = static_cast<int>(fps * 10.0);
    for (int i = 0; i < frames; ++i) total += clock.advance(1.0 / fps);
    EXPECT_NEAR(total, 150, 1) << fps;  // 10 s; ±1 for where the last partial sub-step falls
  }
}

TEST(SubstepClock, SlowFramesRunSeveralSubsteps) {
  SubstepClock clock;
  EXPECT_EQ(clock.advance(0.2 + 1e-9), 3);
  EXPECT_EQ(clock.advance(0.01), 0);
}

TEST(SubstepClock, AnHourLongFrameDoesNotMakeTheCarJump) {
  SubstepClock clock;
  const int due = clock.advance(3600.0);  // window minimised for an hour
  EXPECT_LE(due, 4);
  EXPECT_GE(due, 3);
  EXPECT_LT(clock.phase(), 1.0);
}

TEST(SubstepClock, NegativeOrNanTimeCountsAsNothing) {
  SubstepClock clock;
  EXPECT_EQ(clock.advance(-5.0), 0);
  EXPECT_EQ(clock.advance(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(clock.phase(), 0.0);
}

TEST(SubstepClock, ResetDropsAccumulatedTime) {
  SubstepClock clock;
  clock.advance(0.06);
  EXPECT_GT(clock.phase(), 0.8);
  clock.reset();
  EXPECT_EQ(clock.advance(0.01), 0);
}

TEST(SubstepClock, RejectsInconsistentSettings) {
  EXPECT_THROW(SubstepClock(0.0, 0.25), InputError);
  EXPECT_THROW(SubstepClock(0.5, 0.25), InputError);
  EXPECT_THROW(SubstepClock(std::numeric_limits<double>::quiet_NaN(), 0.25), InputError);
}

}  // namespace
}  // namespace sc::input
