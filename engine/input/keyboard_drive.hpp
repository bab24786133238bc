#pragma once
// Keyboard driving: a held key commands full deflection (±1) on its axis, 0 when released; with Shift held the
// steering keys give half lock, because the expert steers between straight and full lock most of the time and a
// key alone cannot. Arrows and WASD both work; the mapping is the driver's view (up/W = forward, down/S =
// reverse/brake, left/A and right/D = steer) rather than the upstream pygame handler's.
// Difference from the reference (reference-facts §1.9 holds a key at ±0.7), on purpose: the expert's plans keep
// the pedal at its limit nearly all the time, so at ±0.7 a keyboard learner cannot make the expert's motion
// (docs/skills.md, *Keys at full deflection*).
// A second difference, on purpose: there the last key event wins and any key-up zeroes the axis,
// so holding Left, tapping Right and releasing it leaves the wheels straight while Left is still held.
// Here the action is a function of which keys are held: opposite keys cancel, releasing one of them
// restores the other, and arrows and WASD for the same direction do not double up.
#include <cstdint>

#include "engine/input/drive_action.hpp"

namespace sc::input {

enum class DriveKey : std::uint8_t { Up, Down, Left, Right, W, A, S, D, LeftShift, RightShift };

class KeyboardDrive {
 public:
  static constexpr double kKeyAction = 1.0;    // the reference's is 0.7 (above)
  static constexpr double kGentleSteer = 0.5;  // a steering key with Shift held

  void set_pressed(DriveKey key, bool pressed);
  // Window lost focus: key-up events will not arrive, so forget every held key.
  void release_all() { held_ = 0; }
  bool pressed(DriveKey key) const;
  DriveAction action() const;

 private:
  std::uint16_t held_ = 0;  // one bit per DriveKey
};

}  // namespace sc::input
