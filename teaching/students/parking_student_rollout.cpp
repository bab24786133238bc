#include "teaching/students/parking_student_rollout.hpp"

#include <algorithm>

namespace sc {

ParkingTrial rollout_parking_student(const BcPolicy& policy, const ParkingScenario& scenario) {
  ParkingSim sim(scenario);
  ParkingTrial trial;
  trial.scenario = scenario;
  trial.source = "student";
  trial.states.push_back(sim.observation());
  std::vector<float> input(trial.states.back().size());
  while (!sim.done()) {
    const ParkingObservation& o = trial.states.back();
    std::transform(o.begin(), o.end(), input.begin(), [](double v) { return static_cast<float>(v); });
    const std::vector<float> u = policy.act(input);
    const ParkingAction action{u.at(0), u.at(1)};
    const ParkingStepResult r = sim.step(action);
    trial.actions.push_back(action);
    trial.rewards.push_back(r.reward);
    trial.states.push_back(sim.observation());
  }
  trial.success = sim.succeeded();
  return trial;
}

double parking_episode_score(const ParkingTrial& trial) {
  if (trial.rewards.empty())
    return std::min(parking_reward(make_observation(initial_vehicle_state(trial.scenario), goal_pose(trial.scenario))),
                    0.0);
  return std::min(trial.rewards.back(), 0.0);
}

double parking_mean_step_reward(const ParkingTrial& trial) {
  if (trial.rewards.empty()) return parking_episode_score(trial);
  double total = 0.0;
  for (double r : trial.rewards) total += r;
  return total / static_cast<double>(trial.rewards.size());
}

ParkingScore score_parking_student(const BcPolicy& policy, const std::vector<ParkingScenario>& scenarios) {
  ParkingScore score;
  if (scenarios.empty()) return score;
  for (const ParkingScenario& s : scenarios) {
    const ParkingTrial t = rollout_parking_student(policy, s);
    score.mean_reward += parking_episode_score(t);
    score.step_reward += parking_mean_step_reward(t);
    score.success_rate += t.success.value_or(false) ? 1.0 : 0.0;
  }
  score.mean_reward /= static_cast<double>(scenarios.size());
  score.step_reward /= static_cast<double>(scenarios.size());
  score.success_rate /= static_cast<double>(scenarios.size());
  return score;
}

}  // namespace sc
