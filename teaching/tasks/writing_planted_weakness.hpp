#pragma once
// Planted-weakness recovery under realistic input (evaluate-skills --planted-weaknesses): does Alg. 2
// (diagnose_trials, as the app runs it) find the letter a learner writes badly when everything else is
// written with a realistic hand rather than the expert's exact gold?
//
// A planted learner writes the app's pre-test words (Alg. 1's 5 diverse words of the kit's pool) with a
// realistic background hand (paper's drawers, smooth wobble 2..6 px, per-letter affine 0.08, mouse
// sampling, hesitations) and one letter badly, its fault chosen by the learner's index:
//   distorted     the letter's steps squashed or stretched (y scale 0.4..0.6 or 1.6..2), sheared 0.5..0.8;
//   other drawer  the letter in another drawer's shape (any of the 14 other Omniglot drawers; the report
//                 splits these learners by other_drawer_shape_score, since some drawers' letters are close
//                 to the expert's);
//   straight line a straight line from where the letter starts to where it ends (same number of points).
// A noise-only learner has the background hand only. All seeded: learner i of letter L uses
// Rng(seed).fork(1000 * L + i).
// With own hands, every learner writes all its letters in the shape of one unseen drawer (11..15, drawn per
// learner; the other-drawer fault then takes a drawer other than that one), as real learners do: the table
// then asks whether the fault is found when nothing the learner writes is the expert's shape.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/writing/writing_trial.hpp"
#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {

enum class LetterFault { None, Distorted, OtherDrawer, StraightLine };
std::string to_string(LetterFault fault);

struct PlantedLearner {
  char letter = 0;  // 0 with LetterFault::None
  LetterFault fault = LetterFault::None;
  std::uint64_t seed = 0;
  int hand_drawer = 0;  // whose shapes the learner's letters have: 0 the paper's, else that Omniglot drawer's
};

// The learner's trial for `word` (word_index keeps the trials of one learner independent).
writing::WritingTrial planted_trial(const ClassicDrawerGlyphs& glyphs, const std::string& word,
                                    const PlantedLearner& learner, int word_index);

// The learner's trials (documents) of the pre-test `words`, word i from planted_trial(..., i).
std::vector<Json> planted_pretest_trials(const ClassicDrawerGlyphs& glyphs, const std::vector<std::string>& words,
                                         const PlantedLearner& learner);
// The app's pre-test: Alg. 1's diverse words of the kit's pool.
std::vector<std::string> pretest_words(const WritingKit& kit);
// Noise-only learner `index` of a run with `seed` (the planted table's noise-only row).
PlantedLearner noise_only_learner(std::uint64_t seed, int index);
// An unseen drawer (unseen_drawers()) drawn from the learner's seed: its own hand in an own-hands table.
int own_hand_drawer(const PlantedLearner& learner);

// Expertise below this (Alg. 2's E_m, <= 0) counts as a confident target. Why this value: one missing
// skill in one trial with reward -0.3 (a mediocre pre-test word) at position j = 2 costs 0.15; a noise-only
// learner should not lose more than that on any skill.
inline constexpr double kConfidentTargetExpertise = -0.15;

struct PlantedLetterRow {
  char letter = 0;
  int skill = -1;  // the skill with the most expert steps in the letter
  int learners = 0;
  int top_target = 0;                  // learners whose first target is `skill`
  std::vector<int> by_fault_learners;  // per fault (Distorted, OtherDrawer, StraightLine)
  std::vector<int> by_fault_top;
};

// How far `drawer`'s `letter` is from the expert's (the paper's drawer), by the execution score quality-aware
// expertise charges (writing_execution.hpp): both written cleanly, aligned by dynamic time warping, the other
// moved by the mean offset; 0 = the same shape. Why: another drawer's letter is a fault only as far as its shape
// differs, and some drawers' letters are as close to the expert's as realistic noise leaves the expert's own
// (docs/skills.md, "Copies by other hands").
double other_drawer_shape_score(const ClassicDrawerGlyphs& glyphs, char letter, int drawer);

struct OtherDrawerCell {
  int learners = 0;
  int found = 0;             // learners whose first target is the letter's skill
  double shape_score = 0.0;  // other_drawer_shape_score
};

struct PlantedWeaknessReport {
  bool own_hands = false;
  std::vector<std::string> pretest_words;
  std::vector<PlantedLetterRow> letters;
  int noise_learners = 0;
  int noise_without_confident_target = 0;  // no target with expertise < kConfidentTargetExpertise
  // The same over the targets the trainer would drill: the ranking without skills too brief to drill alone
  // (teachable_skills.hpp), as many as there are targets.
  int noise_without_confident_drill_target = 0;
  std::vector<double> noise_lowest_expertise;  // per noise-only learner: its weakest target's E
  std::map<int, int> noise_top_targets;        // skill -> noise-only learners with it as first target
  // Other-drawer learners by letter and the drawer whose shape they write.
  std::map<std::pair<char, int>, OtherDrawerCell> other_drawers;
  std::optional<NoiseFloor> noise_floor;  // the kit's (WritingKit::execution_noise_floor); splits other_drawers
};

// `mode`: the expertise estimate the diagnosis uses (Alg. 2, the app's default, or quality-aware); the
// confident-target threshold is the same for both.
PlantedWeaknessReport measure_planted_weaknesses(const WritingKit& kit, const ClassicDrawerGlyphs& glyphs,
                                                 int learners_per_letter, std::uint64_t seed,
                                                 ExpertiseMode mode = ExpertiseMode::Alg2, bool own_hands = false);

std::string planted_weakness_table(const PlantedWeaknessReport& report);

}  // namespace sc
