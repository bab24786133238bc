#include "engine/input/keyboard_drive.hpp"

namespace sc::input {
namespace {

std::uint16_t bit(DriveKey key) { return static_cast<std::uint16_t>(1u << static_cast<unsigned>(key)); }

}  // namespace

void KeyboardDrive::set_pressed(DriveKey key, bool pressed) {
  if (pressed)
    held_ = static_cast<std::uint16_t>(held_ | bit(key));
  else
    held_ = static_cast<std::uint16_t>(held_ & ~bit(key));
}

bool KeyboardDrive::pressed(DriveKey key) const { return (held_ & bit(key)) != 0; }

DriveAction KeyboardDrive::action() const {
  const int forward = pressed(DriveKey::Up) || pressed(DriveKey::W) ? 1 : 0;
  const int reverse = pressed(DriveKey::Down) || pressed(DriveKey::S) ? 1 : 0;
  const int right = pressed(DriveKey::Right) || pressed(DriveKey::D) ? 1 : 0;
  const int left = pressed(DriveKey::Left) || pressed(DriveKey::A) ? 1 : 0;
  const bool gentle = pressed(DriveKey::LeftShift) || pressed(DriveKey::RightShift);
  return {kKeyAction * (forward - reverse), (gentle ? kGentleSteer : kKeyAction) * (right - left)};
}

}  // namespace sc::input
