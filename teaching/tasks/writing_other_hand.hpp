#pragma once
// The expert's word written by another hand, with the expert's boundaries carried over by alignment:
// training copies that show the skill model a letter drawn differently (train-skills --augment-other-hands).
//
// Why: every other augmentation perturbs the expert's own glyphs, so the model learns the paper's five letter
// shapes and gives a letter by another drawer a skill of its own about half the time (docs/skills.md,
// "Robustness on realistic learners: writing"). Copies by other drawers fix that only if they carry the
// clean word's boundaries and units, and the rule is that copies inherit the clean word's
// *repetition* boundaries, never the generator's true ones. Another hand's copy has other step indices, so
// the inheritance goes through an alignment that knows only that both traces write the same word - what a
// data set of the same words written by several people gives - never where its letters begin.
//
// Spec: both traces are placed in the clean word's frame (each relative to its first point, the copy scaled
// so that both bounding boxes have the clean word's width and height) and aligned by dynamic time warping
// (align_traces). A clean boundary b (a point index) goes to the first copy point aligned with clean point b.
// Mapped boundaries that do not stay strictly ascending inside the copy are dropped; `kept` says which.
// (A third coordinate, the point's share of the path length, was tried and carried fewer letter starts
// to within 5 % of the word: writing_other_hand_test.cpp measures the aligner.)
#include <vector>

#include "teaching/expertise/trace_alignment.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {

struct CarriedBoundaries {
  std::vector<int> boundaries;  // point indices of `copy`, ascending, in (0, copy.points.size() - 1)
  std::vector<bool> kept;       // per clean boundary: whether it has a place in `boundaries`
};
CarriedBoundaries carried_boundaries(const WrittenWord& clean, const WrittenWord& copy,
                                     const std::vector<int>& clean_boundaries);

// The alignment carried_boundaries uses: (clean point, copy point) pairs of two non-empty traces of the same
// word, both placed in the clean trace's frame.
StepAlignment align_same_word(const std::vector<writing::TracePoint>& clean,
                              const std::vector<writing::TracePoint>& copy);
// The same on the pen positions of two writing step sequences (writing_trace_points): (clean step, copy step).
StepAlignment align_same_word(const StepSequence& clean, const StepSequence& copy);

}  // namespace sc
