#pragma once
// The reference's kinematic bicycle model (highway-env Vehicle, reference-facts §1.3-1.5), one sub-step at a
// time. Kept separate from ParkingSim so the expert planner can differentiate exactly the same update.
#include <array>
#include <numbers>

namespace sc {

// Constants of the reference environment (reference-facts §1.1, §1.3, §1.4).
namespace parking {
inline constexpr double kCarLength = 5.0;                     // m, position = centre of the body
inline constexpr double kCarWidth = 2.0;                      // m
inline constexpr double kHalfLength = kCarLength / 2;         // the model's lr = lf = L/2
inline constexpr double kMaxSpeed = 40.0;                     // m/s
inline constexpr double kMaxAcceleration = 5.0;               // m/s^2 at |u0| = 1
inline constexpr double kMaxSteering = std::numbers::pi / 4;  // rad at |u1| = 1
inline constexpr int kSimulationHz = 15;
inline constexpr int kControlHz = 5;
inline constexpr int kSubstepsPerAction = kSimulationHz / kControlHz;  // 3
inline constexpr double kDt = 1.0 / kSimulationHz;
inline constexpr int kHorizon = 100;  // control steps per episode (20 s)
}  // namespace parking

// u0 = acceleration, u1 = steering, each in [-1, 1] (values outside are clipped, as in the reference).
using ParkingAction = std::array<double, 2>;

struct VehicleState {
  double x = 0.0;
  double y = 0.0;
  double heading = 0.0;  // rad, never wrapped (as in the reference)
  double speed = 0.0;    // m/s along the heading; negative when reversing
  bool operator==(const VehicleState&) const = default;
};

// Clips an action to [-1, 1]^2 (NaN becomes 0 so a corrupt input can never poison the state).
ParkingAction clip_action(const ParkingAction& action);
// Physical controls of a clipped action: acceleration 5*u0 m/s^2, steering (pi/4)*u1 rad.
double acceleration_of(const ParkingAction& clipped);
double steering_of(const ParkingAction& clipped);

// One 1/15 s sub-step of the bicycle model with the given acceleration (m/s^2) and steering angle (rad),
// in the reference's exact order (speed guard, slip angle, position, heading, speed).
VehicleState bicycle_substep(const VehicleState& state, double acceleration, double steering);

}  // namespace sc
