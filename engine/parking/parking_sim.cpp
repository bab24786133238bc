#include "engine/parking/parking_sim.hpp"

#include <cmath>
#include <stdexcept>

namespace sc {

ParkingObservation make_observation(const VehicleState& s, const Pose& goal) {
  // The reported velocity ignores the slip angle (reference-facts §1.5); cos(pi/2) stays 6.1e-17 as upstream.
  const double c = std::cos(s.heading);
  const double sn = std::sin(s.heading);
  return {s.x / 100.0, s.y / 100.0, s.speed * c / 5.0,      s.speed * sn / 5.0,
          c,           sn,          goal.x / 100.0,         goal.y / 100.0,
          0.0,         0.0,         std::cos(goal.heading), std::sin(goal.heading)};
}

double parking_goal_distance(const ParkingObservation& o) {
  double sum = 0.0;
  for (int i = 0; i < 6; ++i) sum += parking::kRewardWeights[i] * std::fabs(o[i] - o[i + 6]);
  return sum;
}

double parking_reward(const ParkingObservation& o) { return -std::sqrt(parking_goal_distance(o)); }

ParkingSim::ParkingSim(const ParkingScenario& scenario)
    : scenario_(scenario), layout_(make_layout(scenario)), collisions_(layout_), goal_(goal_pose(scenario)) {
  reset();
}

void ParkingSim::reset() {
  vehicle_ = initial_vehicle_state(scenario_);
  steering_ = 0.0;
  steps_ = 0;
  done_ = succeeded_ = collided_ = false;
}

ParkingStepResult ParkingSim::step(const ParkingAction& action) { return step_substeps({action, action, action}); }

ParkingStepResult ParkingSim::step_substeps(const std::array<ParkingAction, parking::kSubstepsPerAction>& actions) {
  if (done_) throw std::logic_error("ParkingSim::step after the episode ended");
  for (const auto& raw : actions) {
    const ParkingAction u = clip_action(raw);
    steering_ = steering_of(u);
    vehicle_ = bicycle_substep(vehicle_, acceleration_of(u), steering_);
    if (collisions_.has_obstacles() && collisions_.car_collides(vehicle_)) {
      // highway-env sets a crashed car's speed to that of the (static) obstacle, i.e. 0, and a crashed
      // car then brakes with a = -v and no steering, so it stays put for the rest of the control step.
      vehicle_.speed = 0.0;
      collided_ = true;
      break;
    }
  }
  ++steps_;
  ParkingStepResult r;
  r.reward = parking_reward(observation());
  r.collision = collided_;
  // A crash into a parked car is never a successful parking, even inside the goal tolerance.
  r.success = !r.collision && is_success_reward(r.reward);
  if (r.collision) r.reward += parking::kCollisionReward;
  succeeded_ = r.success;
  r.done = r.success || r.collision || steps_ >= parking::kHorizon;
  done_ = r.done;
  return r;
}

}  // namespace sc
