#pragma once
// Gamepad axes -> DriveAction, independent of SDL so it can be tested with any values, including the
// broken ones a faulty driver or a replayed device log can produce (NaN, Inf, out of range).
#include "engine/input/drive_action.hpp"

namespace sc::input {

enum class ThrottleControl {
  LeftStick,  // left stick: x = steering, y = throttle (up = forward, down = brake/reverse)
  Triggers,   // right trigger = forward, left trigger = reverse, left stick x = steering
};

struct GamepadConfig {
  ThrottleControl throttle = ThrottleControl::LeftStick;
  // Fractions of full deflection. Worn sticks rest up to ~0.1 off centre, so the default is a bit above.
  double stick_dead_zone = 0.12;
  double trigger_dead_zone = 0.05;
};

// Throws InputError("gamepad config", ...) unless both dead zones are finite and within [0, 0.9].
void validate(const GamepadConfig& config);

// Normalised axis values as SDL's GameController API reports them after scaling: sticks in [-1, 1] with
// y pointing DOWN (SDL convention: pushing the stick up gives negative y), triggers in [0, 1].
struct GamepadSample {
  double left_x = 0.0;
  double left_y = 0.0;
  double left_trigger = 0.0;
  double right_trigger = 0.0;
};

struct InputReading {
  DriveAction action;
  bool faulty = false;  // an axis the mapping reads was NaN, infinite or out of range
};

// Maps one sample. If any axis the chosen mode reads is NaN/Inf or outside its range, the whole action is
// neutral (0, 0) and `faulty` is set: a device that sends garbage on one axis cannot be trusted on the other,
// and a car that coasts with straight wheels is the safe state.
// Stick mode: radial dead zone with rescaling, then the disc->square map (stick_geometry.hpp) so every
// action in [-1,1]^2 is reachable. Trigger mode: per-axis dead zones; accel = right - left.
InputReading map_gamepad(const GamepadSample& sample, const GamepadConfig& config);

}  // namespace sc::input
