#include "engine/input/keyboard_drive.hpp"

#include <gtest/gtest.h>

namespace sc::input {
namespace {

TEST(KeyboardDrive, HeldKeyGivesFullDeflectionAndReleaseGivesZero) {
  KeyboardDrive k;
  k.set_pressed(DriveKey::Up, true);
  EXPECT_EQ(k.action(), (DriveAction{1.0, 0.0}));
  k.set_pressed(DriveKey::Up, false);
  EXPECT_EQ(k.action(), (DriveAction{0.0, 0.0}));
  k.set_pressed(DriveKey::Down, true);
  k.set_pressed(DriveKey::Left, true);
  EXPECT_EQ(k.action(), (DriveAction{-1.0, -1.0}));
  k.set_pressed(DriveKey::Left, false);
  k.set_pressed(DriveKey::Right, true);
  EXPECT_EQ(k.action(), (DriveAction{-1.0, 1.0}));
}

TEST(KeyboardDrive, OppositeKeysCancelAndReleasingOneRestoresTheOther) {
  KeyboardDrive k;
  k.set_pressed(DriveKey::Left, true);
  k.set_pressed(DriveKey::Right, true);
  EXPECT_EQ(k.action().steer, 0.0);
  k.set_pressed(DriveKey::Right, false);  // the reference would leave 0 here although Left is held
  EXPECT_EQ(k.action().steer, -1.0);
  k.set_pressed(DriveKey::W, true);
  k.set_pressed(DriveKey::S, true);
  EXPECT_EQ(k.action().accel, 0.0);
}

TEST(KeyboardDrive, ArrowsAndWasdForTheSameDirectionDoNotAddUp) {
  KeyboardDrive k;
  k.set_pressed(DriveKey::Up, true);
  k.set_pressed(DriveKey::W, true);
  EXPECT_EQ(k.action().accel, 1.0);
  k.set_pressed(DriveKey::W, false);
  EXPECT_EQ(k.action().accel, 1.0);  // Up still held
  k.set_pressed(DriveKey::D, true);
  k.set_pressed(DriveKey::Right, true);
  EXPECT_EQ(k.action().steer, 1.0);
}

TEST(KeyboardDrive, EitherShiftHalvesTheSteeringKeysButNotThePedal) {
  KeyboardDrive k;
  k.set_pressed(DriveKey::Up, true);
  k.set_pressed(DriveKey::Left, true);
  k.set_pressed(DriveKey::LeftShift, true);
  EXPECT_EQ(k.action(), (DriveAction{1.0, -0.5}));
  k.set_pressed(DriveKey::RightShift, true);
  k.set_pressed(DriveKey::LeftShift, false);  // the other Shift is still held
  EXPECT_EQ(k.action(), (DriveAction{1.0, -0.5}));
  k.set_pressed(DriveKey::RightShift, false);
  EXPECT_EQ(k.action(), (DriveAction{1.0, -1.0}));
}

TEST(KeyboardDrive, ReleaseAllForgetsEveryKey) {
  KeyboardDrive k;
  for (DriveKey key : {DriveKey::Up, DriveKey::A, DriveKey::Right, DriveKey::RightShift}) k.set_pressed(key, true);
  k.release_all();
  EXPECT_EQ(k.action(), DriveAction{});
  EXPECT_FALSE(k.pressed(DriveKey::Up));
}

}  // namespace
}  // namespace sc::input
