#include "engine/input/gamepad_mapping.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/input/stick_geometry.hpp"

namespace sc::input {
namespace {

constexpr double kMaxDeadZone = 0.9;

void check_dead_zone(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0 || value > kMaxDeadZone)
    throw InputError("gamepad config", std::string(name) + " = " + std::to_string(value) + " is outside [0, 0.9]");
}

bool valid_stick_axis(double v) { return std::isfinite(v) && v >= -1.0 && v <= 1.0; }
bool valid_trigger_axis(double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; }

InputReading map_left_stick(const GamepadSample& s, const GamepadConfig& config) {
  if (!valid_stick_axis(s.left_x) || !valid_stick_axis(s.left_y)) return {{}, true};
  // Stick up (negative SDL y) is forward, hence the sign flip.
  const Vec2 disc = rescale_radial_dead_zone({s.left_x, -s.left_y}, config.stick_dead_zone);
  const Vec2 square = disc_to_square(disc);
  return {{square.y, square.x}, false};
}

InputReading map_triggers(const GamepadSample& s, const GamepadConfig& config) {
  if (!valid_stick_axis(s.left_x) || !valid_trigger_axis(s.left_trigger) || !valid_trigger_axis(s.right_trigger))
    return {{}, true};
  const double forward = rescale_axial_dead_zone(s.right_trigger, config.trigger_dead_zone);
  const double reverse = rescale_axial_dead_zone(s.left_trigger, config.trigger_dead_zone);
  const double steer = rescale_axial_dead_zone(s.left_x, config.stick_dead_zone);
  return {{forward - reverse, steer}, false};
}

}  // namespace

void validate(const GamepadConfig& config) {
  check_dead_zone(config.stick_dead_zone, "stick_dead_zone");
  check_dead_zone(config.trigger_dead_zone, "trigger_dead_zone");
}

InputReading map_gamepad(const GamepadSample& sample, const GamepadConfig& config) {
  return config.throttle == ThrottleControl::Triggers ? map_triggers(sample, config) : map_left_stick(sample, config);
}

}  // namespace sc::input
