#pragma once
// Unsupervised boundaries from exact repetition: Harris's successor variety on a corpus of demonstrations.
//
// Why: CompILE's relaxed objective, trained from random weights on the writing words, settles on stroke
// pieces although letter segments score better on the same objective (docs/skills.md, "Does the letter
// segmentation score better"). The expert's words are concatenations of a few symbols whose raw pen steps
// repeat exactly, so the places where the corpus stops predicting the next step are where one symbol
// ends and another begins. These boundaries warm-start CompILE (CompileTrainer::warm_start); nothing here
// reads the true boundaries.
//
// Each action becomes a token (its coordinates rounded to `token_precision`). Between actions p-1 and p,
//   forward variety  = number of distinct tokens that follow the `context` tokens before p anywhere in the
//                      corpus (contexts clipped at the demonstration's start are keyed with their length),
//   backward variety = number of distinct tokens that precede the `context` tokens from p on.
// Inside a repeated symbol both are 1 (its own next and previous steps); where symbols meet at least one
// exceeds 1 wherever the corpus holds that symbol in two contexts. Each demonstration keeps at most
// `max_boundaries` positions, strongest first (both varieties > 1 before one; then the larger sum, then
// the earlier position), at least `min_separation` actions apart.
//
// Only meaningful for data that repeat exactly (the writing expert's words); on continuous actions
// (parking) every context is unique and nothing is found.
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct RepeatBoundaryConfig {
  int context = 64;               // tokens of context on each side
  int max_boundaries = 7;         // per demonstration (CompILE: K - 1)
  int min_separation = 1;         // actions between two kept boundaries
  double token_precision = 1e-4;  // coordinates equal up to this count as the same step
};

// Interior boundaries (action indices in 1..T-1, ascending) of every demonstration, parallel to `demos`.
std::vector<std::vector<int>> find_repeat_boundaries(const std::vector<StepSequence>& demos,
                                                     const RepeatBoundaryConfig& config = {});

// Which repeated unit each segment is: segment j of demo i runs from boundary j-1 to boundary j of
// `boundaries[i]` (interior action indices, as find_repeat_boundaries returns them). Segments whose actions
// are equal step for step (up to `token_precision`) are one unit; units seen at least twice get ids
// 0, 1, ... by how often they occur (most frequent first, ties by first appearance), at most `max_units`
// of them; every other segment gets -1. Why: the warm start can then also give each repeated unit a skill
// of its own (CompileConfig::warm_start_units), instead of hoping that reconstruction alone keeps two
// letters apart; like the boundaries, this reads only what repeats, never the true symbols.
std::vector<std::vector<int>> repeat_units(const std::vector<StepSequence>& demos,
                                           const std::vector<std::vector<int>>& boundaries, int max_units,
                                           double token_precision = RepeatBoundaryConfig{}.token_precision);

}  // namespace sc
