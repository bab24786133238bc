#pragma once
// Other right ways to do the expert's trial, for quality-aware expertise (execution_expertise.hpp).
//
// Why: the execution term scores each expert segment against the expert's own way of doing it. For a
// learner who does the whole task in another accepted way - writes every letter in a hand of their own -
// every segment then looks like an error, and the one skill they really do badly no longer stands out
// (docs/skills.md, "Learners in their own hand": 41-48 of 100 planted letters found, a noise-only learner
// told to drill a letter they write well in their own hand). A task may therefore give references: the
// expert's trial done the other ways (writing: the same word in other drawers' hands). The learner's hand
// is the reference that fits all of their segments best (estimate_execution_expertise); a segment is then
// scored against the expert and that reference, whichever it is closer to.
//
// Spec: a reference's steps are in the expert's frame (the task's trace_points compare them with the
// learner's directly); from_expert pairs each expert step with the reference's steps that do the same
// thing, in order (dynamic time warping or the like): it says which part of the reference does each expert
// segment. The learner's trace is aligned with each reference directly (execution_trial in
// teaching/sessions/session_analysis.hpp), not through its alignment with the expert: a learner who writes
// in a reference's hand matches that reference step by step, and carried through the expert's other shape
// the pairs went astray (docs/skills.md, "Aligned with the hand itself").
#include <string>
#include <vector>

#include "teaching/expertise/trace_alignment.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct ExecutionReference {
  std::string name;           // what a person calls it, e.g. "the letters of Omniglot drawer 4"
  StepSequence steps;         // the expert's trial done this way, in the expert's frame
  StepAlignment from_expert;  // (expert step, reference step) pairs, ascending in both
};

}  // namespace sc
