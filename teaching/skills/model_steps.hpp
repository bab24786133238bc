#pragma once
// The steps CompILE actually sees, and the way back to the trajectory's own action indices.
//
// Writing trajectories are 1-px pen steps (T ~ 1250..2700 per word). Segmenting them needs far fewer
// steps, and the model's cost is linear in T (the reference needed 415 s per batch at T ~ 2600), so a
// config may resample by arc length: actions are read as displacements, consecutive actions are grouped
// until their path length reaches `step`, and the group becomes one model step whose action is the mean
// unit direction (displacement / path length, so every coordinate stays inside the decoder's tanh range)
// and whose state is the state before the group's first action. `original_begin[j]` keeps the first
// original action of model step j, so a boundary found at model step j maps back to action index
// original_begin[j]; original_begin[T'] = T closes the last group. With step = 0 the mapping is identity.
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct ModelSteps {
  StepSequence steps;               // what the model sees (T' steps)
  std::vector<int> original_begin;  // T' + 1 entries, strictly increasing, from 0 to T
};

// `phase` (0 <= phase < resample_step) is path counted as already walked before the first action, so the
// first group is that much shorter and every later group edge moves accordingly (phase_vote.hpp).
ModelSteps to_model_steps(const StepSequence& trajectory, double resample_step, double phase = 0.0);

// Maps a segmentation in model steps back to original action indices (still covering [0, T)).
Segmentation to_original_indices(const Segmentation& model_segments, const ModelSteps& steps);

// Reference readout (reference-facts §3.7): segment k runs from the largest earlier boundary to its own
// boundary; the last segment ends at `length`. Empty segments (start >= end, which happens when a later
// boundary falls before an earlier one) are dropped, so the result covers [0, length) without gaps.
Segmentation segments_from_boundaries(const std::vector<int>& boundaries, const std::vector<int>& skills, int length);

}  // namespace sc
