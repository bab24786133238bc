#pragma once
// ParkingSim: the reference Parking environment (reference-facts §1), plus our parked-car variant.
// One step() = one 5 Hz control step = 3 sub-steps of 1/15 s with the action held. The observation is
// the reference's 12-D rollout state [ego 6, goal 6] in scaled units; reward and success are computed on
// the post-step observation. step() allocates nothing.
#include <array>

#include "engine/parking/collision_checker.hpp"
#include "engine/parking/parking_scenario.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {

// [x/100, y/100, vx/5, vy/5, cos h, sin h, goal x/100, goal y/100, 0, 0, cos hg, sin hg]
using ParkingObservation = std::array<double, 12>;

namespace parking {
inline constexpr std::array<double, 6> kRewardWeights{1.0, 0.3, 0.0, 0.0, 0.02, 0.02};
inline constexpr double kSuccessReward = -0.12;   // success when reward > -0.12
inline constexpr double kCollisionReward = -5.0;  // added on the step that collides (never used upstream)
}  // namespace parking

ParkingObservation make_observation(const VehicleState& state, const Pose& goal);
// -(sum_i w_i |o_i - g_i|)^0.5 over the ego half and the goal half of the observation.
double parking_reward(const ParkingObservation& observation);
// The weighted distance inside the square root (success when < 0.0144).
double parking_goal_distance(const ParkingObservation& observation);
inline bool is_success_reward(double reward) { return reward > parking::kSuccessReward; }

struct ParkingStepResult {
  double reward = 0.0;  // includes the collision penalty on a colliding step
  bool success = false;
  bool collision = false;
  bool done = false;  // success, collision or the 100-step horizon
};

class ParkingSim {
 public:
  explicit ParkingSim(const ParkingScenario& scenario);

  // Back to the start of the episode (the layout is kept).
  void reset();
  // One control step with the action held for 3 sub-steps. Throws std::logic_error once done().
  ParkingStepResult step(const ParkingAction& action);
  // One control step with a separate action per sub-step (for input applied at the simulation rate).
  ParkingStepResult step_substeps(const std::array<ParkingAction, parking::kSubstepsPerAction>& actions);

  const ParkingScenario& scenario() const { return scenario_; }
  const ParkingLayout& layout() const { return layout_; }
  const Pose& goal() const { return goal_; }
  const VehicleState& vehicle() const { return vehicle_; }
  double steering() const { return steering_; }  // rad, of the last sub-step (for drawing the wheels)
  ParkingObservation observation() const { return make_observation(vehicle_, goal_); }
  int steps() const { return steps_; }
  bool done() const { return done_; }
  bool succeeded() const { return succeeded_; }
  bool collided() const { return collided_; }

 private:
  ParkingScenario scenario_;
  ParkingLayout layout_;
  CollisionChecker collisions_;
  Pose goal_;
  VehicleState vehicle_;
  double steering_ = 0.0;
  int steps_ = 0;
  bool done_ = false;
  bool succeeded_ = false;
  bool collided_ = false;
};

}  // namespace sc
