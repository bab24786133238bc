#pragma once
// How well a learner's pen did an expert's skill segment, in the writing score's own terms (quality-aware
// expertise, teaching/expertise/execution_expertise.hpp).
//
// Spec. The expert's pen points of the segment [begin, end) and the learner's points aligned with them are
// compared as writing_score.hpp compares ink: recall = mean credit of the expert's points (distance to the
// nearest aligned learner point), precision = mean credit of the learner's aligned points (distance to the
// nearest expert point of the segment), credit 1 within the score's tolerance (3 px) falling linearly to 0
// at its cutoff (8 px); the segment's score is recall * precision - 1. Pen positions are absolute (the
// learner traces on the expert's canvas), so no frame change is needed.
#include <vector>

#include "teaching/expertise/trace_alignment.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// (x px, y px, 0) per step of a writing StepSequence.
std::vector<TracePoint3> writing_trace_points(const StepSequence& steps);

// In [-1, 0]; 0 when every expert point of the segment and every aligned learner point lie within the
// tolerance of the other's.
double writing_execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                int begin, int end);

}  // namespace sc
