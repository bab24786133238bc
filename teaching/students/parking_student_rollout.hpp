#pragma once
// A behaviour-cloned student driving ParkingSim on its own: at every 5 Hz control step it sees the 12-D
// goal-conditioned observation and its (tanh-bounded) action is applied for the step, until the car parks,
// collides or the 100-step horizon ends. The score is the reference's episode score, the last step's reward
// (<= 0, like ParkingKit::reward_of), so Alg. 2 and the evaluation read the same number.
#include <vector>

#include "engine/parking/parking_trial.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

// The episode as a trial (source "student"): T actions, T+1 observations, T rewards, success.
ParkingTrial rollout_parking_student(const BcPolicy& policy, const ParkingScenario& scenario);

// min(last reward, 0); the start's reward when the episode has no steps.
double parking_episode_score(const ParkingTrial& trial);

struct ParkingScore {
  double mean_reward = 0.0;   // mean episode score (last-step reward) over the scenarios
  double step_reward = 0.0;   // mean over the scenarios of the episode's mean per-step reward
  double success_rate = 0.0;  // share of episodes that parked
};

// The episode's mean per-step reward (the start's reward when it has no steps): unlike the last step's
// reward it also counts how the car got there.
double parking_mean_step_reward(const ParkingTrial& trial);

ParkingScore score_parking_student(const BcPolicy& policy, const std::vector<ParkingScenario>& scenarios);

}  // namespace sc
