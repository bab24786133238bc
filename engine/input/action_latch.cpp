#include "engine/input/action_latch.hpp"

#include <stdexcept>
#include <string>

namespace sc::input {

const DriveAction& RecordedActions::action_for_substep(std::int64_t substep) const {
  if (substep < 0 || substep >= substep_count())
    throw std::out_of_range("recorded actions cover " + std::to_string(substep_count()) +
                            " sub-steps, asked for sub-step " + std::to_string(substep));
  return actions[static_cast<std::size_t>(substep / substeps_per_action)];
}

int substeps_per_action(ActionTiming timing) {
  return timing == ActionTiming::Responsive ? 1 : kSubstepsPerControlStep;
}

ActionLatch::ActionLatch(ActionTiming timing) : timing_(timing) {
  recorded_.substeps_per_action = substeps_per_action(timing);
}

const DriveAction& ActionLatch::next_substep(const DriveAction& live) {
  if (samples_next()) recorded_.actions.push_back(sanitized(live));
  ++substeps_done_;
  return recorded_.actions.back();
}

}  // namespace sc::input
