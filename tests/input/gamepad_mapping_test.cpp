#include "engine/input/gamepad_mapping.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc::input {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

GamepadConfig triggers_config() {
  GamepadConfig c;
  c.throttle = ThrottleControl::Triggers;
  return c;
}

TEST(GamepadMapping, RestingStickIsNeutral) {
  const InputReading r = map_gamepad({}, GamepadConfig{});
  EXPECT_EQ(r.action, DriveAction{});
  EXPECT_FALSE(r.faulty);
}

TEST(GamepadMapping, StickUpIsForwardAndRightIsRightSteering) {
  EXPECT_EQ(map_gamepad({0.0, -1.0, 0, 0}, {}).action, (DriveAction{1.0, 0.0}));
  EXPECT_EQ(map_gamepad({0.0, 1.0, 0, 0}, {}).action, (DriveAction{-1.0, 0.0}));
  EXPECT_EQ(map_gamepad({1.0, 0.0, 0, 0}, {}).action, (DriveAction{0.0, 1.0}));
  EXPECT_EQ(map_gamepad({-1.0, 0.0, 0, 0}, {}).action, (DriveAction{0.0, -1.0}));
}

TEST(GamepadMapping, DeadZoneIsRadialAndRescaled) {
  GamepadConfig c;
  c.stick_dead_zone = 0.2;
  // (0.15, -0.15) has length 0.21 > 0.2 although each axis alone is inside: radial, not per axis.
  EXPECT_EQ(map_gamepad({0.14, -0.14, 0, 0}, c).action, DriveAction{});
  const DriveAction just_out = map_gamepad({0.15, -0.15, 0, 0}, c).action;
  EXPECT_GT(just_out.accel, 0.0);
  EXPECT_LT(just_out.accel, 0.02);
  // Half way between dead zone and rim on the x axis gives half steering.
  EXPECT_DOUBLE_EQ(map_gamepad({0.6, 0.0, 0, 0}, c).action.steer, 0.5);
}

TEST(GamepadMapping, FullDiagonalReachesTheActionSquareCorner) {
  const DriveAction a = map_gamepad({std::sqrt(0.5), -std::sqrt(0.5), 0, 0}, {}).action;
  EXPECT_NEAR(a.accel, 1.0, 1e-12);
  EXPECT_NEAR(a.steer, 1.0, 1e-12);
}

TEST(GamepadMapping, NonFiniteOrOutOfRangeAxesGiveNeutralAndAreFlagged) {
  for (const GamepadSample& s :
       {GamepadSample{kNaN, -1.0, 0, 0}, GamepadSample{0.5, kInf, 0, 0}, GamepadSample{0.5, -kInf, 0, 0},
        GamepadSample{1.5, 0.0, 0, 0}, GamepadSample{0.0, -1.0001, 0, 0}}) {
    const InputReading r = map_gamepad(s, {});
    EXPECT_TRUE(r.faulty) << s.left_x << " " << s.left_y;
    EXPECT_EQ(r.action, DriveAction{}) << s.left_x << " " << s.left_y;
  }
}

TEST(GamepadMapping, TriggerModeRightForwardLeftReverse) {
  const GamepadConfig c = triggers_config();
  EXPECT_EQ(map_gamepad({0, 0, 0.0, 1.0}, c).action, (DriveAction{1.0, 0.0}));
  EXPECT_EQ(map_gamepad({0, 0, 1.0, 0.0}, c).action, (DriveAction{-1.0, 0.0}));
  EXPECT_EQ(map_gamepad({0, 0, 1.0, 1.0}, c).action, (DriveAction{0.0, 0.0}));
  EXPECT_EQ(map_gamepad({-1.0, 0, 0.0, 1.0}, c).action, (DriveAction{1.0, -1.0}));
}

TEST(GamepadMapping, TriggerModeIgnoresStickYAndHasItsOwnDeadZone) {
  GamepadConfig c = triggers_config();
  c.trigger_dead_zone = 0.1;
  EXPECT_EQ(map_gamepad({0, -1.0, 0, 0.05}, c).action, DriveAction{});
  EXPECT_DOUBLE_EQ(map_gamepad({0, 0, 0, 0.55}, c).action.accel, 0.5);
  // Stick y is not read in trigger mode, so garbage there does not stop the car being driven.
  const InputReading r = map_gamepad({0, kNaN, 0, 1.0}, c);
  EXPECT_FALSE(r.faulty);
  EXPECT_EQ(r.action.accel, 1.0);
}

TEST(GamepadMapping, TriggerModeFlagsBrokenTriggers) {
  const GamepadConfig c = triggers_config();
  for (const GamepadSample& s : {GamepadSample{0, 0, kNaN, 0}, GamepadSample{0, 0, 0, -0.5},
                                 GamepadSample{0, 0, 0, 2.0}, GamepadSample{kNaN, 0, 0, 1.0}}) {
    const InputReading r = map_gamepad(s, c);
    EXPECT_TRUE(r.faulty);
    EXPECT_EQ(r.action, DriveAction{});
  }
}

TEST(GamepadConfigValidation, RejectsDeadZonesOutsideTheUsableRange) {
  EXPECT_NO_THROW(validate(GamepadConfig{}));
  for (double bad : {-0.1, 0.95, 1.0, kNaN}) {
    GamepadConfig c;
    c.stick_dead_zone = bad;
    EXPECT_THROW(validate(c), InputError) << bad;
    GamepadConfig t;
    t.trigger_dead_zone = bad;
    EXPECT_THROW(validate(t), InputError) << bad;
  }
  GamepadConfig c;
  c.stick_dead_zone = 2.0;
  try {
    validate(c);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stick_dead_zone"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc::input
