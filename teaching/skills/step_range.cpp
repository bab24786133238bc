#include "teaching/skills/step_range.hpp"

#include <cstddef>

namespace sc {

StepSequence steps_between(const StepSequence& steps, int begin, int end) {
  StepSequence out;
  out.state_dim = steps.state_dim;
  out.action_dim = steps.action_dim;
  const auto s = static_cast<std::ptrdiff_t>(steps.state_dim);
  const auto a = static_cast<std::ptrdiff_t>(steps.action_dim);
  if (!steps.states.empty()) out.states.assign(steps.states.begin() + begin * s, steps.states.begin() + end * s);
  out.actions.assign(steps.actions.begin() + begin * a, steps.actions.begin() + end * a);
  return out;
}

Segmentation shifted(Segmentation segmentation, int offset) {
  for (SkillSegment& s : segmentation.segments) {
    s.begin += offset;
    s.end += offset;
  }
  return segmentation;
}

}  // namespace sc
