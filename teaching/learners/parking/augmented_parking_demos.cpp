#include "teaching/learners/parking/augmented_parking_demos.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking/parking_trial.hpp"
#include "teaching/learners/parking/realistic_driver.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

constexpr std::uint64_t kAugmentStream = 0xa06d0;

SkillDemo realistic_copy(const ParkingTrial& expert, const std::string& label, const Rng& plan_rng, int copy) {
  Rng rng = plan_rng.fork(1u + static_cast<std::uint64_t>(copy));
  const auto device = static_cast<DriveDevice>(rng.below(3));
  const RealisticDriverProfile profile = sample_novice_profile(device, rng);
  const ParkingTrial drive = realistic_drive(expert, profile, rng);
  return {
      label + " (" + device_name(device) + " copy " + std::to_string(copy + 1) + ")", parking_step_sequence(drive), {}};
}

}  // namespace

SkillDataSet generate_augmented_parking_demos(int count, int copies, std::uint64_t seed, bool keyed_copy) {
  if (count < 1 || copies < 0)
    throw InputError("parking demonstrations", "count must be at least 1, copies at least 0");
  const ParkingExpert expert;
  const Rng root = Rng(seed).fork(kAugmentStream);
  SkillDataSet out{"parking", "", {}, {}, {}};
  int parked = 0;
  for (int i = 0; i < count; ++i) {
    const ParkingScenario scenario = parking_pool_scenario(seed, i);
    const ParkingTrial trial = expert.plan(scenario).to_trial(scenario);
    if (!trial.success.value_or(false)) continue;
    ++parked;
    const std::string label = "scenario " + std::to_string(i);
    out.demos.push_back({label, parking_step_sequence(trial), {}});
    const Rng plan_rng = root.fork(static_cast<std::uint64_t>(i));
    const std::size_t clean = out.demos.size() - 1;
    for (int c = 0; c < copies; ++c) out.demos.push_back(realistic_copy(trial, label, plan_rng, c));
    if (keyed_copy) out.demos.push_back({label + " (keyboard keys)", with_keyboard_keys(out.demos[clean].steps), {}});
  }
  out.description = std::to_string(parked) + " parked ParkingExpert plans out of " + std::to_string(count) +
                    " random classic scenarios (parking_pool_scenario(seed " + std::to_string(seed) + ", 0.." +
                    std::to_string(count - 1) + ")), plus " + std::to_string(copies) +
                    " realistic copies each (novice profile, device drawn per copy, 15 Hz input)" +
                    (keyed_copy ? " and one with keyboard keys for actions on the clean states" : "");
  return out;
}

}  // namespace sc
