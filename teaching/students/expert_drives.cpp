#include "teaching/students/expert_drives.hpp"

#include <algorithm>

#include "engine/parking/parking_expert.hpp"
#include "teaching/students/bc_datasets.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

// The pairs whose first action component is negative (reverse) or not.
BcDataset pairs_by_sign(const BcDataset& data, bool reverse) {
  BcDataset out;
  out.state_dim = data.state_dim;
  out.action_dim = data.action_dim;
  for (int i = 0; i < data.size(); ++i) {
    const std::size_t a = static_cast<std::size_t>(i * data.action_dim);
    if ((data.actions[a] < 0.0f) != reverse) continue;
    const auto s = data.states.begin() + static_cast<std::ptrdiff_t>(i * data.state_dim);
    out.states.insert(out.states.end(), s, s + data.state_dim);
    const auto u = data.actions.begin() + static_cast<std::ptrdiff_t>(a);
    out.actions.insert(out.actions.end(), u, u + data.action_dim);
  }
  return out;
}

}  // namespace

std::vector<ParkingTrial> plan_expert_drives(int count, std::uint64_t seed, GoalRegion region,
                                             const std::function<void(int)>& progress) {
  const ParkingExpert expert;
  std::vector<ParkingTrial> trials;
  trials.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    const ParkingScenario scenario = parking_pool_scenario(seed, i, region);
    trials.push_back(expert.plan(scenario).to_trial(scenario));
    if (progress) progress(i + 1);
  }
  return trials;
}

BcDataset bc_dataset_from_trials(const std::vector<ParkingTrial>& trials) {
  std::vector<StepSequence> steps;
  steps.reserve(trials.size());
  for (const ParkingTrial& t : trials) steps.push_back(parking_step_sequence(t));
  return bc_dataset_from_steps(steps);
}

SplitMse split_mse(const BcPolicy& policy, const BcDataset& data) {
  return SplitMse{policy.evaluate(data), policy.evaluate(pairs_by_sign(data, true)),
                  policy.evaluate(pairs_by_sign(data, false))};
}

}  // namespace sc
