#pragma once
// How well a writing skill model holds on realistic learners (evaluate-skills --robustness): for each
// condition, classic words written by realistic hands (writing_realistic_learner.hpp), segmented by the
// model, scored against the generator's true symbol boundaries (boundary F1 within +-5 % of the word, as
// evaluate-skills) and by letter->skill agreement: the share of the words' letters (a b c t e, not the
// connectors) whose majority skill (by steps) equals the majority skill the model gives the same letter of
// the expert's gold word. The true boundaries are only used for scoring.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "teaching/skills/segmentation_metrics.hpp"
#include "teaching/skills/skill_extractor.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {

struct WritingCondition {
  std::string name;
  std::optional<RealisticHand> hand;  // nullopt: the expert's gold words themselves
};

// expert gold; mouse sampling; wobble 5 px; wobble 10 px; unseen drawers (11..15, with mouse sampling);
// a realistic mix (unseen drawers, 5 px wobble, affine 0.1, mouse sampling and hesitations); then, to tell
// the causes apart, single perturbations without mouse sampling: 5 px wobble, affine 0.1, training drawers.
std::vector<WritingCondition> writing_robustness_conditions();

struct WritingRobustnessRow {
  std::string condition;
  BoundaryScore boundaries;
  int letters = 0;
  int agreeing = 0;
  double agreement() const { return letters > 0 ? static_cast<double>(agreeing) / letters : 0.0; }
};

// One row per condition on `words`; word i of a condition is written with seed Rng(seed).fork(i).
std::vector<WritingRobustnessRow> measure_writing_robustness(const SkillExtractor& extractor,
                                                             const ClassicDrawerGlyphs& glyphs,
                                                             const std::vector<std::string>& words, std::uint64_t seed,
                                                             const std::vector<WritingCondition>& conditions);

// The majority skill (by steps) over actions [begin, end); -1 for an empty range.
int majority_skill(const Segmentation& segmentation, int begin, int end);

// A Markdown table: condition, boundary F1 (P / R), letter->skill agreement.
std::string robustness_table(const std::vector<WritingRobustnessRow>& rows);

}  // namespace sc
