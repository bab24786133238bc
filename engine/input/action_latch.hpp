#pragma once
// When the learner's input reaches the car, and what gets recorded so the trial replays exactly.
//
// The parking environment simulates at 15 Hz and takes a new action every 3 sub-steps (5 Hz, 0.2 s;
// reference-facts §1.4). Two timings:
//  - Latched (default): the live input is sampled at the first sub-step of each control step and held for
//    3 sub-steps, exactly like the environment does with the expert's actions, so learner and expert
//    trajectories have the same form and are directly comparable. One recorded action per control step.
//  - Responsive: the live input is sampled at every sub-step (1/15 s latency instead of up to 0.2 s).
//    One recorded action per sub-step; the trial must store substeps_per_action = 1 so a replay applies
//    each recorded action to a single sub-step.
// The action returned to the simulation is the very object that was recorded (after sanitising), so
// replaying RecordedActions::action_for_substep() through the same simulation reproduces it bit for bit.
#include <cstdint>
#include <vector>

#include "engine/input/drive_action.hpp"

namespace sc::input {

// 15 Hz simulation / 5 Hz control (reference §1.4).
inline constexpr int kSubstepsPerControlStep = 3;

enum class ActionTiming { Latched, Responsive };

// The actions of one trial as they were applied. Trajectory files store `actions` as [[u0, u1], ...]
// and, only when it is not 3, `"action_substeps": substeps_per_action`.
struct RecordedActions {
  int substeps_per_action = kSubstepsPerControlStep;  // 3 (latched) or 1 (responsive)
  std::vector<DriveAction> actions;

  // Number of simulation sub-steps these actions cover.
  std::int64_t substep_count() const { return static_cast<std::int64_t>(actions.size()) * substeps_per_action; }
  // The action applied during simulation sub-step `substep` (0-based from the start of the trial).
  // Throws std::out_of_range past the end.
  const DriveAction& action_for_substep(std::int64_t substep) const;
};

int substeps_per_action(ActionTiming timing);

class ActionLatch {
 public:
  explicit ActionLatch(ActionTiming timing = ActionTiming::Latched);

  // Call exactly once before each simulation sub-step, in order. When this sub-step starts a new action
  // period, `live` is sanitised, recorded and latched; returns the action to apply during this sub-step.
  const DriveAction& next_substep(const DriveAction& live);

  // True when the next call to next_substep() will sample the live input (for a "latched" indicator).
  bool samples_next() const { return substeps_done_ % recorded_.substeps_per_action == 0; }
  std::int64_t substeps_done() const { return substeps_done_; }
  ActionTiming timing() const { return timing_; }
  const RecordedActions& recorded() const { return recorded_; }

 private:
  ActionTiming timing_;
  RecordedActions recorded_;
  std::int64_t substeps_done_ = 0;
};

}  // namespace sc::input
