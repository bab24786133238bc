#include "engine/input/virtual_joystick.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc::input {
namespace {

constexpr Vec2 kCentre{200.0, 150.0};
constexpr double kRadius = 50.0;

TEST(VirtualJoystick, PressOutsideTheBaseIsIgnored) {
  VirtualJoystick stick(kCentre, kRadius);
  EXPECT_FALSE(stick.press({200.0, 201.0}));
  EXPECT_FALSE(stick.grabbed());
  stick.drag({200.0, 100.0});  // dragging without a grab does nothing
  EXPECT_EQ(stick.action(), DriveAction{});
  EXPECT_EQ(stick.view().knob, kCentre);
  EXPECT_FALSE(stick.press({std::numeric_limits<double>::quiet_NaN(), 150.0}));
}

TEST(VirtualJoystick, UpIsForwardRightIsRightSteering) {
  VirtualJoystick stick(kCentre, kRadius);
  ASSERT_TRUE(stick.press({200.0, 100.0}));  // top of the base
  EXPECT_EQ(stick.action(), (DriveAction{1.0, 0.0}));
  stick.drag({250.0, 150.0});
  EXPECT_EQ(stick.action(), (DriveAction{0.0, 1.0}));
  stick.drag({200.0, 175.0});  // half way down: half reverse
  EXPECT_EQ(stick.action(), (DriveAction{-0.5, 0.0}));
  EXPECT_EQ(stick.view().knob, (Vec2{200.0, 175.0}));
}

TEST(VirtualJoystick, KnobIsClampedToTheCircleAlongThePointerDirection) {
  VirtualJoystick stick(kCentre, kRadius);
  ASSERT_TRUE(stick.press(kCentre));
  stick.drag({200.0 + 300.0, 150.0 - 400.0});  // far away, direction (0.6, -0.8)
  const JoystickView v = stick.view();
  EXPECT_NEAR(v.knob.x, 200.0 + 30.0, 1e-12);
  EXPECT_NEAR(v.knob.y, 150.0 - 40.0, 1e-12);
  // On the rim, the action lies on the border of the square: accel 1, steer 0.6/0.8.
  EXPECT_NEAR(stick.action().accel, 1.0, 1e-15);
  EXPECT_NEAR(stick.action().steer, 0.75, 1e-15);
}

TEST(VirtualJoystick, ReleaseReturnsTheKnobToTheCentre) {
  VirtualJoystick stick(kCentre, kRadius);
  ASSERT_TRUE(stick.press({230.0, 130.0}));
  EXPECT_NE(stick.action(), DriveAction{});
  stick.release();
  EXPECT_FALSE(stick.grabbed());
  EXPECT_EQ(stick.action(), DriveAction{});
  EXPECT_EQ(stick.view().knob, kCentre);
}

TEST(VirtualJoystick, MovingTheBaseKeepsTheHeldAction) {
  VirtualJoystick stick(kCentre, kRadius);
  ASSERT_TRUE(stick.press({220.0, 150.0}));
  const DriveAction before = stick.action();
  stick.set_base({400.0, 300.0}, 100.0);
  EXPECT_EQ(stick.action(), before);
  EXPECT_EQ(stick.view().knob, (Vec2{440.0, 300.0}));
}

TEST(VirtualJoystick, RejectsADegenerateBase) {
  EXPECT_THROW(VirtualJoystick(kCentre, 0.0), InputError);
  EXPECT_THROW(VirtualJoystick(kCentre, -3.0), InputError);
  EXPECT_THROW(VirtualJoystick({std::numeric_limits<double>::infinity(), 0.0}, 5.0), InputError);
}

TEST(ExpertStickDisplay, KnobForAnActionDrivesThatActionBack) {
  // Every action of the square, including the golden episode's first expert action, can be shown.
  for (double accel = -1.0; accel <= 1.0; accel += 0.25)
    for (double steer = -1.0; steer <= 1.0; steer += 0.25) {
      const JoystickView v = joystick_view_for_action({accel, steer}, kCentre, kRadius);
      EXPECT_LE(std::hypot(v.knob.x - kCentre.x, v.knob.y - kCentre.y), kRadius * (1.0 + 1e-15));
      const DriveAction back = action_for_knob(v.knob, kCentre, kRadius);
      EXPECT_NEAR(back.accel, accel, 1e-13);
      EXPECT_NEAR(back.steer, steer, 1e-13);
    }
  const JoystickView golden = joystick_view_for_action({0.980399, -0.686609}, kCentre, kRadius);
  EXPECT_LT(golden.knob.x, kCentre.x);  // steering left
  EXPECT_LT(golden.knob.y, kCentre.y);  // forward = up on screen
  const DriveAction back = action_for_knob(golden.knob, kCentre, kRadius);
  EXPECT_NEAR(back.accel, 0.980399, 1e-13);
  EXPECT_NEAR(back.steer, -0.686609, 1e-13);
}

TEST(ExpertStickDisplay, DraggingToTheShownKnobReproducesTheAction) {
  const DriveAction expert{-0.4, 0.9};
  const JoystickView v = joystick_view_for_action(expert, kCentre, kRadius);
  VirtualJoystick stick(kCentre, kRadius);
  ASSERT_TRUE(stick.press(v.knob));
  EXPECT_NEAR(stick.action().accel, expert.accel, 1e-13);
  EXPECT_NEAR(stick.action().steer, expert.steer, 1e-13);
}

TEST(ExpertStickDisplay, InvalidActionsAreShownAsSanitised) {
  const JoystickView v = joystick_view_for_action({std::numeric_limits<double>::quiet_NaN(), 5.0}, kCentre, kRadius);
  EXPECT_NEAR(v.knob.x, kCentre.x + kRadius, 1e-12);  // steer clamped to 1, accel NaN -> 0
  EXPECT_NEAR(v.knob.y, kCentre.y, 1e-12);
}

}  // namespace
}  // namespace sc::input
