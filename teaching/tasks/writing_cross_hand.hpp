#pragma once
// Do a word and the same word by other hands get the same skills? A check that needs no true boundaries.
//
// Why: how well a writing model keeps another drawer's letter on the expert's skill varies with the training
// run far more than its objective shows (training seeds 3, 0, 5 of one recipe: unseen drawers' agreement
// 0.85-0.89, 0.78, 0.61-0.65; docs/skills.md), and the validation NLL that picks a restart does not see it.
// Measuring it with the generator's true letter boundaries is fine for a report, not for choosing a model;
// this measure knows only that both traces write the same word, as carried_boundaries does.
//
// Spec: word i is written cleanly by the paper's drawer and, unsampled and without noise, by drawers drawn per
// letter from a pool `drawers` (realistic_trace, seed Rng(seed).fork(i)); both become the skill model's step
// sequences and are segmented; their steps' pen positions are aligned with align_same_word. The consistency is
// the share of the clean words' steps whose skill equals the skill of the first copy step aligned with it
// (connectors included: the measure does not know where letters are).
#include <cstdint>
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {

struct CrossHandConsistency {
  int steps = 0;
  int agreeing = 0;
  double share() const { return steps > 0 ? static_cast<double>(agreeing) / steps : 0.0; }
};

// One result per drawer pool of `pools` (each as `drawers` in the spec): the clean words are written and
// segmented once for all of them.
std::vector<CrossHandConsistency> cross_hand_consistency(const SkillExtractor& extractor,
                                                         const ClassicDrawerGlyphs& glyphs,
                                                         const std::vector<std::string>& words, std::uint64_t seed,
                                                         const std::vector<std::vector<int>>& pools);

}  // namespace sc
