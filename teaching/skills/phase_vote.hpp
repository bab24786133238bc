#pragma once
// A segmentation that does not depend on where the resampling starts: vote over phases.
//
// Why: a model that resamples by arc length (CompileConfig::resample_step, writing's 8 px) groups the pen
// steps from the trace's first point on, and that start is arbitrary: the same letter drawn 3 px later on
// the page falls into other groups, and a boundary near the edge of a group can move to another letter or
// vanish. Segmenting the trace at P phases (the first group shortened by p / P of a step, p = 0..P-1) and
// keeping what most phases agree on removes that arbitrary choice; on learners' wobbly or other-hand
// letters it measured better letter skills, and mostly better boundaries, than the one reading from the
// first point (docs/skills.md, *Reading at three phases*).
//
// The vote, on the P segmentations of one trajectory of `length` actions (original action indices):
//  * every interior boundary (a segment's begin > 0) of every phase is a candidate; its support is the
//    number of phases with a boundary within `tolerance` actions of it (each phase counted once) and its
//    spread the sum, over those phases, of the distance to their nearest such boundary;
//  * candidates are taken by support (most first), then spread (least first), then position; one is kept
//    when more than half of the phases support it and no boundary kept so far is within `tolerance`;
//  * each segment between kept boundaries gets the skill that the phases give most of its actions (counted
//    over actions and phases; a tie goes to the lowest skill id).
// Deterministic. CompileModel::segment votes only when a model reads more than one phase.
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

Segmentation vote_phases(const std::vector<Segmentation>& phases, int length, int tolerance);

// The tolerance the vote uses for a resampled trajectory: one model step, i.e. the trajectory's actions
// per model step at phase 0, rounded up (at least 1).
int phase_vote_tolerance(int actions, int model_steps);

}  // namespace sc
