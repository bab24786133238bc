#pragma once
// The expert drives the synthetic students learn from, kept apart from the kit's teaching pool.
//
// Why: cloned on the 100-demo pool that also supplies the diagnosis scenarios and every drill, the students
// were data-starved (held-out MSE ~6x the paper's) and failed generically, so the fine-tuning comparison
// measured nothing about skills. ParkingExpert plans are cheap (~30 ms), so the students get their own
// thousand drives and are measured on another set no student or drill ever saw.
#include <cstdint>
#include <functional>
#include <vector>

#include "engine/parking/parking_scenario.hpp"
#include "engine/parking/parking_trial.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

// ParkingExpert plans of scenarios parking_pool_scenario(seed, 0..count-1, region) (count x ~30 ms). progress(done)
// after each plan, if set.
std::vector<ParkingTrial> plan_expert_drives(int count, std::uint64_t seed, GoalRegion region,
                                             const std::function<void(int)>& progress = {});

// Every goal-conditioned (observation, action) pair of the drives.
BcDataset bc_dataset_from_trials(const std::vector<ParkingTrial>& trials);

// Mean squared action error split by the expert's acceleration sign: the reversing student's deficit
// must sit in the u0 < 0 pairs (reversing and braking).
struct SplitMse {
  double all = 0.0;
  double reverse = 0.0;  // pairs with u0 < 0
  double forward = 0.0;  // pairs with u0 >= 0
};
SplitMse split_mse(const BcPolicy& policy, const BcDataset& data);

}  // namespace sc
