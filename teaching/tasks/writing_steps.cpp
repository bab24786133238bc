#include "teaching/tasks/writing_steps.hpp"

#include "engine/writing/infill.hpp"

namespace sc {

StepSequence writing_step_sequence(const writing::WritingStepData& data) {
  StepSequence out;
  out.state_dim = data.state_dim;
  out.action_dim = data.action_dim;
  out.states = data.states;
  out.actions = data.actions;
  return out;
}

StepSequence writing_step_sequence(const writing::WritingTrial& trial) {
  return writing_step_sequence(trial.trace(), trial.scenario.alphabet, trial.scenario.word);
}

StepSequence writing_step_sequence(const writing::TimedTrace& trace, writing::AlphabetKind alphabet,
                                   const std::string& word) {
  const writing::TimedTrace infilled = writing::infill_trace(trace);
  return writing_step_sequence(writing::trace_step_data(infilled.points, alphabet, word));
}

}  // namespace sc
