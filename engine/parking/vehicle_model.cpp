#include "engine/parking/vehicle_model.hpp"

#include <algorithm>
#include <cmath>

namespace sc {

ParkingAction clip_action(const ParkingAction& action) {
  ParkingAction out{};
  for (int i = 0; i < 2; ++i) out[i] = std::isnan(action[i]) ? 0.0 : std::clamp(action[i], -1.0, 1.0);
  return out;
}

double acceleration_of(const ParkingAction& clipped) { return parking::kMaxAcceleration * clipped[0]; }
double steering_of(const ParkingAction& clipped) { return parking::kMaxSteering * clipped[1]; }

VehicleState bicycle_substep(const VehicleState& state, double acceleration, double steering) {
  using namespace parking;
  double a = acceleration;
  // Speed guard, reproduced with the upstream bug (reference-facts §1.5): the reverse branch uses
  // kMaxSpeed - v instead of -kMaxSpeed - v, so below -40 m/s it pushes the speed back by ~5.4 m/s in one
  // sub-step instead of holding it at -40 (a jolt rather than a cap). Kept on purpose so recorded reference
  // episodes replay bit-for-bit; it only matters after ~8 s of full reverse throttle, which no expert and
  // no sensible learner does (reference expert speeds stay below 17.2 m/s).
  if (state.speed > kMaxSpeed) a = std::min(a, kMaxSpeed - state.speed);
  if (state.speed < -kMaxSpeed) a = std::max(a, kMaxSpeed - state.speed);
  const double beta = std::atan(0.5 * std::tan(steering));
  VehicleState next = state;
  next.x = state.x + state.speed * std::cos(state.heading + beta) * kDt;
  next.y = state.y + state.speed * std::sin(state.heading + beta) * kDt;
  next.heading = state.heading + state.speed * std::sin(beta) / kHalfLength * kDt;
  next.speed = state.speed + a * kDt;
  return next;
}

}  // namespace sc
