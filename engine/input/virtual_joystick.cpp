#include "engine/input/virtual_joystick.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"

namespace sc::input {
namespace {

void check_base(Vec2 centre, double radius) {
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(radius) || radius <= 0.0)
    throw InputError("virtual joystick",
                     "base needs a finite centre and a radius > 0, got radius " + std::to_string(radius));
}

// Pointer in pixels -> unit-disc offset (y down), clamped to the rim.
Vec2 unit_offset(Vec2 pointer, Vec2 centre, double radius) {
  if (!std::isfinite(pointer.x) || !std::isfinite(pointer.y)) return {};
  return clamp_to_unit_disc({(pointer.x - centre.x) / radius, (pointer.y - centre.y) / radius});
}

DriveAction action_for_offset(Vec2 offset) {
  const Vec2 square = disc_to_square({offset.x, -offset.y});  // screen up = forward
  return {square.y, square.x};
}

Vec2 knob_for_offset(Vec2 offset, Vec2 centre, double radius) {
  return {centre.x + offset.x * radius, centre.y + offset.y * radius};
}

}  // namespace

JoystickView joystick_view_for_action(const DriveAction& u, Vec2 centre, double radius) {
  const DriveAction safe = sanitized(u);
  const Vec2 disc = square_to_disc({safe.steer, safe.accel});
  return {centre, radius, knob_for_offset({disc.x, -disc.y}, centre, radius)};
}

DriveAction action_for_knob(Vec2 knob, Vec2 centre, double radius) {
  return action_for_offset(unit_offset(knob, centre, radius));
}

VirtualJoystick::VirtualJoystick(Vec2 centre, double radius) : centre_(centre), radius_(radius) {
  check_base(centre, radius);
}

void VirtualJoystick::set_base(Vec2 centre, double radius) {
  check_base(centre, radius);
  centre_ = centre;
  radius_ = radius;
}

bool VirtualJoystick::press(Vec2 pointer) {
  const double dx = pointer.x - centre_.x;
  const double dy = pointer.y - centre_.y;
  if (!(std::hypot(dx, dy) <= radius_)) return false;  // also rejects NaN pointers
  grabbed_ = true;
  offset_ = unit_offset(pointer, centre_, radius_);
  return true;
}

void VirtualJoystick::drag(Vec2 pointer) {
  if (grabbed_) offset_ = unit_offset(pointer, centre_, radius_);
}

void VirtualJoystick::release() {
  grabbed_ = false;
  offset_ = {};
}

JoystickView VirtualJoystick::view() const { return {centre_, radius_, knob_for_offset(offset_, centre_, radius_)}; }

DriveAction VirtualJoystick::action() const { return action_for_offset(offset_); }

}  // namespace sc::input
