#include "teaching/tasks/parking_steps.hpp"

#include <algorithm>
#include <cmath>

#include "engine/parking/parking_replay.hpp"

namespace sc {

StepSequence parking_step_sequence(const std::vector<ParkingObservation>& states,
                                   const std::vector<ParkingAction>& actions) {
  StepSequence out;
  out.state_dim = kParkingStateDim;
  out.action_dim = kParkingActionDim;
  const std::size_t t = actions.size();
  out.states.reserve(t * kParkingStateDim);
  out.actions.reserve(t * kParkingActionDim);
  for (std::size_t i = 0; i < t; ++i) {
    const ParkingObservation& s = states.at(std::min(i, states.size() - 1));
    for (double v : s) out.states.push_back(static_cast<float>(v));
    const ParkingAction u = clip_action(actions[i]);
    out.actions.push_back(static_cast<float>(u[0]));
    out.actions.push_back(static_cast<float>(u[1]));
  }
  return out;
}

namespace {

std::vector<ParkingAction> control_rate_actions(const ParkingTrial& trial) {
  if (trial.control_hz == parking::kControlHz) return trial.actions;
  std::vector<ParkingAction> out;
  const std::size_t per = parking::kSubstepsPerAction;
  for (std::size_t i = 0; i + per <= trial.actions.size(); i += per) {
    ParkingAction mean{0.0, 0.0};
    for (std::size_t k = 0; k < per; ++k) {
      const ParkingAction u = clip_action(trial.actions[i + k]);
      mean[0] += u[0] / static_cast<double>(per);
      mean[1] += u[1] / static_cast<double>(per);
    }
    out.push_back(mean);
  }
  return out;
}

// The observation before every control step and after the last, from the shared replay.
std::vector<ParkingObservation> simulate_states(const ParkingTrial& trial) {
  const Pose goal = goal_pose(trial.scenario);
  std::vector<ParkingObservation> states{make_observation(initial_vehicle_state(trial.scenario), goal)};
  for (const ParkingReplayStep& step : replay_parking_trial(trial).steps)
    states.push_back(make_observation(step.vehicle, goal));
  return states;
}

}  // namespace

StepSequence parking_step_sequence(const ParkingTrial& trial) {
  std::vector<ParkingAction> actions = control_rate_actions(trial);
  const bool have_states = trial.states.size() >= actions.size() && !trial.states.empty();
  std::vector<ParkingObservation> states = have_states ? trial.states : simulate_states(trial);
  // An episode ends at success or collision: actions recorded after that never moved the car.
  if (states.size() < actions.size()) actions.resize(states.size() - 1);
  return parking_step_sequence(states, actions);
}

VehicleState vehicle_from_observation(const ParkingObservation& o) {
  VehicleState v;
  v.x = o[0] * 100.0;
  v.y = o[1] * 100.0;
  v.heading = std::atan2(o[5], o[4]);
  v.speed = 5.0 * (o[2] * o[4] + o[3] * o[5]);
  return v;
}

}  // namespace sc
