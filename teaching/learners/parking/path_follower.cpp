#include "teaching/learners/parking/path_follower.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/parking/parking_scenario.hpp"

namespace sc {
namespace {

constexpr std::array<double, 7> kDeltas{0.0, -0.2, 0.2, -0.5, 0.5, -1.0, 1.0};  // 0 first: ties keep the expert's
constexpr double kHeadingArm = parking::kHalfLength;                            // m per rad of heading error
constexpr double kSpeedArm = kFollowerHorizonSubsteps * parking::kDt;           // s: m per m/s of speed error
constexpr double kEffort = 0.01;                                                // per unit of |du|^2

}  // namespace

PathFollower::PathFollower(const ParkingTrial& expert) {
  VehicleState s = initial_vehicle_state(expert.scenario);
  states_.push_back(s);
  for (const ParkingAction& raw : expert.actions) {
    const ParkingAction u = clip_action(raw);
    for (int k = 0; k < parking::kSubstepsPerAction; ++k) {
      s = bicycle_substep(s, acceleration_of(u), steering_of(u));
      actions_.push_back(u);
      states_.push_back(s);
    }
  }
}

const VehicleState& PathFollower::expert_state(int substep) const {
  return states_[static_cast<std::size_t>(std::clamp(substep, 0, substeps()))];
}

ParkingAction PathFollower::expert_action(int substep) const {
  if (substep < 0 || substep >= substeps()) return {0.0, 0.0};
  return actions_[static_cast<std::size_t>(substep)];
}

double PathFollower::miss(const VehicleState& seen, int substep, const ParkingAction& delta) const {
  VehicleState s = seen;
  for (int h = 0; h < kFollowerHorizonSubsteps; ++h) {
    const ParkingAction e = expert_action(substep + h);
    const ParkingAction u = clip_action({e[0] + delta[0], e[1] + delta[1]});
    s = bicycle_substep(s, acceleration_of(u), steering_of(u));
  }
  const VehicleState& goal = expert_state(substep + kFollowerHorizonSubsteps);
  const double dx = s.x - goal.x, dy = s.y - goal.y;
  const double dh = kHeadingArm * std::remainder(s.heading - goal.heading, 2.0 * std::numbers::pi);
  const double dv = kSpeedArm * (s.speed - goal.speed);
  return dx * dx + dy * dy + dh * dh + dv * dv + kEffort * (delta[0] * delta[0] + delta[1] * delta[1]);
}

ParkingAction PathFollower::correction(const VehicleState& seen, int substep) const {
  substep = std::max(substep, 0);
  ParkingAction best{0.0, 0.0};
  double best_miss = std::numeric_limits<double>::infinity();
  for (double d0 : kDeltas)
    for (double d1 : kDeltas) {
      const double m = miss(seen, substep, {d0, d1});
      if (m < best_miss) {
        best_miss = m;
        best = {d0, d1};
      }
    }
  return best;
}

ActuatorLimits actions_at_limits(const std::vector<ParkingTrial>& drives) {
  ActuatorLimits out;
  for (const ParkingTrial& t : drives)
    for (const ParkingAction& raw : t.actions) {
      const ParkingAction u = clip_action(raw);
      ++out.steps;
      out.pedal += std::abs(u[0]) >= kAtLimit;
      out.steering += std::abs(u[1]) >= kAtLimit;
    }
  return out;
}

}  // namespace sc
