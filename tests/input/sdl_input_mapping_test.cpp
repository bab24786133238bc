#include "engine/input/sdl_input_mapping.hpp"

#include <gtest/gtest.h>

namespace sc::input {
namespace {

TEST(SdlAxes, FullRangeMapsExactlyOntoTheUnitInterval) {
  EXPECT_EQ(normalized_stick_axis(-32768), -1.0);
  EXPECT_EQ(normalized_stick_axis(32767), 1.0);
  EXPECT_EQ(normalized_stick_axis(0), 0.0);
  EXPECT_DOUBLE_EQ(normalized_stick_axis(-16384), -0.5);
  EXPECT_EQ(normalized_trigger_axis(32767), 1.0);
  EXPECT_EQ(normalized_trigger_axis(0), 0.0);
  EXPECT_EQ(normalized_trigger_axis(-32768), 0.0);  // a driver bug, read as released
}

TEST(SdlAxes, EveryRawValueIsAValidGamepadInput) {
  for (int raw = -32768; raw <= 32767; raw += 7) {
    const auto v = static_cast<Sint16>(raw);
    const InputReading r = map_gamepad(
        {normalized_stick_axis(v), normalized_stick_axis(v), normalized_trigger_axis(v), normalized_trigger_axis(v)},
        {});
    ASSERT_FALSE(r.faulty) << raw;
  }
}

TEST(SdlKeys, ArrowsAndWasdByPhysicalPosition) {
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_UP), DriveKey::Up);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_DOWN), DriveKey::Down);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_LEFT), DriveKey::Left);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_RIGHT), DriveKey::Right);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_W), DriveKey::W);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_A), DriveKey::A);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_S), DriveKey::S);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_D), DriveKey::D);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_LSHIFT), DriveKey::LeftShift);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_RSHIFT), DriveKey::RightShift);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_Q), std::nullopt);
  EXPECT_EQ(drive_key_for_scancode(SDL_SCANCODE_SPACE), std::nullopt);
}

}  // namespace
}  // namespace sc::input
