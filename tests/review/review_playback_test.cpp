#include "teaching/review/review_playback.hpp"

#include <gtest/gtest.h>

namespace sc::review {
namespace {

TEST(Playback, StartsPausedAtTheEndAndPlaysFromTheStart) {
  Playback p;
  p.load(10, 0.2);
  EXPECT_FALSE(p.playing());
  EXPECT_DOUBLE_EQ(p.position(), 10.0);
  p.play();
  EXPECT_TRUE(p.playing());
  EXPECT_DOUBLE_EQ(p.position(), 0.0);
  p.advance(0.5);  // 2.5 steps of 0.2 s at 1x
  EXPECT_NEAR(p.position(), 2.5, 1e-12);
  EXPECT_EQ(p.current_step(), 2);
  EXPECT_NEAR(p.seconds(), 0.5, 1e-12);
}

TEST(Playback, SpeedScalesTimeAndIsClamped) {
  Playback p;
  p.load(100, 0.2);
  p.play();
  p.set_speed(4.0);
  p.advance(0.1);
  EXPECT_NEAR(p.position(), 2.0, 1e-12);
  p.set_speed(0.25);
  p.advance(0.8);
  EXPECT_NEAR(p.position(), 3.0, 1e-12);
  p.set_speed(10.0);
  EXPECT_DOUBLE_EQ(p.speed(), 4.0);
  p.set_speed(0.0);
  EXPECT_DOUBLE_EQ(p.speed(), 0.25);
}

TEST(Playback, StopsAtTheEndPausesAndScrubs) {
  Playback p;
  p.load(5, 0.2);
  p.play();
  p.advance(10.0);
  EXPECT_FALSE(p.playing());
  EXPECT_DOUBLE_EQ(p.position(), 5.0);
  EXPECT_EQ(p.current_step(), 4);
  p.scrub(-3.0);
  EXPECT_DOUBLE_EQ(p.position(), 0.0);
  p.scrub(2.25);
  p.toggle();
  p.toggle();
  p.advance(1.0);  // paused: no movement
  EXPECT_DOUBLE_EQ(p.position(), 2.25);
}

}  // namespace
}  // namespace sc::review
