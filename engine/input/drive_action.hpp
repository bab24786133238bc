#pragma once
// The learner's command to the parking car, in the environment's action space u in [-1,1]^2
// (reference-facts §1.4): u0 = acceleration (5·u0 m/s^2, negative = brake/reverse), u1 = steering
// ((π/4)·u1 rad). Positive steering turns the car clockwise on screen (world y points down), i.e. to the
// driver's right when driving forward - so "stick right" maps to u1 > 0 on every device.
namespace sc::input {

struct DriveAction {
  double accel = 0.0;  // u0
  double steer = 0.0;  // u1
  friend bool operator==(const DriveAction&, const DriveAction&) = default;
};

// Each component clamped to [-1, 1]; NaN/Inf components become 0 (neutral: no throttle, wheels straight).
// The environment would clip too, but we sanitise before recording so the file holds exactly what was applied.
DriveAction sanitized(const DriveAction& action);

// True when both components are finite and within [-1, 1].
bool is_valid(const DriveAction& action);

}  // namespace sc::input
