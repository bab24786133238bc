#pragma once
// Re-simulates a trial's actions from its scenario (what `skillcoach replay --task parking` prints).
#include <vector>

#include "engine/parking/parking_sim.hpp"
#include "engine/parking/parking_trial.hpp"

namespace sc {

struct ParkingReplayStep {
  int t = 0;             // 1-based control step
  VehicleState vehicle;  // after the step
  double reward = 0.0;
  bool success = false;
};

struct ParkingReplay {
  std::vector<ParkingReplayStep> steps;
  double total_return = 0.0;
  int success_step = -1;  // 1-based control step of success, -1 if never
  bool collision = false;
  int ignored_actions = 0;  // actions left over after the episode ended (success/collision/horizon)
};

ParkingReplay replay_parking_trial(const ParkingTrial& trial);

}  // namespace sc
