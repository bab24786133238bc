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
#include <map>
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"
#include "teaching/tasks/writing_other_hand.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {

struct CrossHandConsistency {
  int steps = 0;
  int agreeing = 0;
  std::map<int, int> clean_skills, copy_skills;  // per skill: clean steps, and aligned copy steps, that have it
  double share() const { return steps > 0 ? static_cast<double>(agreeing) / steps : 0.0; }
  // Cohen's kappa: the share beyond what the two skill frequencies give by chance. A model that gives every
  // step one skill is perfectly consistent (share 1) and scores 0 here, so only kappa may choose a model.
  double kappa() const;
};

// The check's traces, written and aligned once (the alignment is most of the cost and needs no model), so
// several models - a training's restarts - are measured on them by segmenting only. One pool per entry of
// `pools` (each as `drawers` in the spec); measure() gives one result per pool.
class CrossHandWords {
 public:
  CrossHandWords(const ClassicDrawerGlyphs& glyphs, const std::vector<std::string>& words, std::uint64_t seed,
                 const std::vector<std::vector<int>>& pools);
  std::vector<CrossHandConsistency> measure(const SkillExtractor& extractor) const;

 private:
  struct Pool {
    std::vector<StepSequence> copies;
    std::vector<StepAlignment> paths;  // clean word i's steps -> copy i's (align_same_word)
  };
  std::vector<StepSequence> clean_;
  std::vector<Pool> pools_;
};

// CrossHandWords(glyphs, words, seed, pools).measure(extractor).
std::vector<CrossHandConsistency> cross_hand_consistency(const SkillExtractor& extractor,
                                                         const ClassicDrawerGlyphs& glyphs,
                                                         const std::vector<std::string>& words, std::uint64_t seed,
                                                         const std::vector<std::vector<int>>& pools);

// The restart choice's check (train-skills for writing; restart_choice.hpp): consistency with drawers 1-10 only
// (training's own hands, so the unseen drawers stay for measuring) on `words` classic words of
// Rng(training seed).fork(kRestartCheckStream), a seed no table uses; the score is the consistency's kappa.
struct RestartCrossHandCheck {
  int words = 400;
  std::uint64_t seed = 0;
  std::string describe() const;  // for the model's sidecar
};
inline constexpr std::uint64_t kRestartCheckStream = 0x726573746172ULL;  // "restar"
RestartCrossHandCheck restart_cross_hand_check(std::uint64_t training_seed, int words = RestartCrossHandCheck{}.words);
CrossHandWords restart_check_words(const ClassicDrawerGlyphs& glyphs, const RestartCrossHandCheck& check);
double restart_cross_hand_score(const SkillExtractor& extractor, const CrossHandWords& check_words);  // kappa

}  // namespace sc
