#pragma once
// Part of a trajectory, and a segmentation of that part placed back on the whole: what reading a trajectory in parts
// (a drive's moving part, pieces of a long drive) needs on both sides of the wrapped extractor.
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// Steps [begin, end) of `steps`, states and actions (states only when it has any). Requires 0 <= begin <= end <= T.
StepSequence steps_between(const StepSequence& steps, int begin, int end);

// Every segment moved `offset` steps later.
Segmentation shifted(Segmentation segmentation, int offset);

}  // namespace sc
