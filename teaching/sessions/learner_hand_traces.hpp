#pragma once
// The learner's hand as something to look at: when quality-aware expertise took one of the kit's references as
// the learner's hand (ExpertiseEstimate::learner_hand, teaching/expertise/execution_reference.hpp), the trainer's
// diagnosis page and the instructor's review draw one pre-test trial over the guide and over that hand. This
// gathers the three traces, in the task's own coordinates (TaskKit::trace_points' x and y).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "teaching/sessions/task_kit.hpp"

namespace sc {

struct LearnerHandTraces {
  std::vector<std::pair<double, double>> learner, guide, hand;
};

// `learner_trial` (a trial document) on the scenario whose expert steps are `expert`; nullopt when `hand` is empty
// or none of the kit's references for that scenario has that name.
std::optional<LearnerHandTraces> learner_hand_traces(const TaskKit& kit, const Json& scenario,
                                                     const StepSequence& expert, const Json& learner_trial,
                                                     const std::string& hand);

}  // namespace sc
