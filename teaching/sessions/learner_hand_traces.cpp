#include "teaching/sessions/learner_hand_traces.hpp"

#include <algorithm>

namespace sc {
namespace {

std::vector<std::pair<double, double>> xy_of(const TaskKit& kit, const StepSequence& steps) {
  std::vector<std::pair<double, double>> out;
  for (const TracePoint3& p : kit.trace_points(steps)) out.emplace_back(p[0], p[1]);
  return out;
}

}  // namespace

std::optional<LearnerHandTraces> learner_hand_traces(const TaskKit& kit, const Json& scenario,
                                                     const StepSequence& expert, const Json& learner_trial,
                                                     const std::string& hand) {
  if (hand.empty()) return std::nullopt;
  const std::vector<ExecutionReference> references = kit.execution_references(scenario, expert);
  const auto found = std::find_if(references.begin(), references.end(),
                                  [&hand](const ExecutionReference& r) { return r.name == hand; });
  if (found == references.end()) return std::nullopt;
  return LearnerHandTraces{xy_of(kit, kit.steps_of(learner_trial)), xy_of(kit, expert), xy_of(kit, found->steps)};
}

}  // namespace sc
