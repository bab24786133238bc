#pragma once
// How well a learner's pen did an expert's skill segment, in the writing score's own terms (quality-aware
// expertise, teaching/expertise/execution_expertise.hpp).
//
// Spec. The expert's pen points of the segment [begin, end) and the learner's points aligned with them are
// compared as writing_score.hpp compares ink: recall = mean credit of the expert's points (distance to the
// nearest aligned learner point), precision = mean credit of the learner's aligned points (distance to the
// nearest expert point of the segment), credit 1 within the score's tolerance (3 px) falling linearly to 0
// at its cutoff (8 px); the segment's score is recall * precision - 1. The learner's points are first laid over
// the expert's: moved so the aligned pairs' centroids meet, and scaled about it by the ratio of the pairs'
// root-mean-square distances from their centroids (at most kMaxSizeRatio either way). The segment's shape is
// scored, not where it lies or how large it is: an earlier letter's drift, a word written a little higher, or a
// letter traced a little larger is not this skill's error (parking likewise compares motion from each part's
// own start). A squashed or sheared letter, or a line for a letter, keeps its other shape. Measured: scoring
// absolute positions let the short connectors, which carry the drift of the letters before them, dominate every
// diagnosis; scoring sizes too missed planted letters among learners whose letters vary in size
// (docs/skills.md).
#include <vector>

#include "teaching/expertise/trace_alignment.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// A letter more than twice or less than half the expert's size is not rescaled further: a dot or a collapsed
// stroke is not blown up into a letter.
inline constexpr double kMaxSizeRatio = 2.0;

// (x px, y px, 0) per step of a writing StepSequence.
std::vector<TracePoint3> writing_trace_points(const StepSequence& steps);

// In [-1, 0]; 0 when every expert point of the segment and every aligned learner point lie within the
// tolerance of the other's.
double writing_execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                int begin, int end);

}  // namespace sc
