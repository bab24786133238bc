#pragma once
// How well a learner's drive did an expert's skill segment, in the parking reward's own terms (quality-aware
// expertise, teaching/expertise/execution_expertise.hpp).
//
// Spec. Each part is seen from where it starts: the motion at step i of the expert's segment is its pose
// relative to the segment's first pose (displacement rotated into that pose's heading, heading change),
// likewise the learner's motion relative to the first learner step aligned with the segment. For every
// aligned pair the reward's formula is applied to the two relative motions, -(Σ w_k |a_k - b_k|)^0.5 with
// the reward's weights (1 and 0.3 on the displacement /100 m along and across the start heading, 0.02 on
// cos and sin of the heading change; 0 on velocity, as in the reward); the segment's score is the mean over
// its pairs. Seen from the part's start, drift accumulated before the segment does not count against it.
#include <vector>

#include "teaching/expertise/trace_alignment.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// (x m, y m, signed speed m/s) per step of a parking StepSequence (12-D states).
std::vector<TracePoint3> parking_trace_points(const StepSequence& steps);

// <= 0; 0 when the learner's aligned part moves exactly as the expert's segment [begin, end).
double parking_execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                int begin, int end);

}  // namespace sc
