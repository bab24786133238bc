#include "teaching/tasks/writing_cross_hand.hpp"

#include <gtest/gtest.h>

#include "engine/core/asset_paths.hpp"
#include "engine/writing/word_generator.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc {
namespace {

const ClassicDrawerGlyphs& cross_hand_glyphs() {
  static const ClassicDrawerGlyphs g = ClassicDrawerGlyphs::load();
  return g;
}

TEST(WritingCrossHand, TheSameHandIsFullyConsistent) {
  const TimeHeuristicExtractor slices(8);
  const std::vector<std::string> words = writing::classic_words(5, 3);
  const std::vector<CrossHandConsistency> both =
      cross_hand_consistency(slices, cross_hand_glyphs(), words, 3, {{}, training_drawers()});
  const CrossHandConsistency& same = both[0];
  EXPECT_GT(same.steps, 0);
  EXPECT_EQ(same.agreeing, same.steps);
  const CrossHandConsistency& other = both[1];
  EXPECT_LT(other.share(), 1.0);
}

// A model that gives every step one skill agrees with any other hand, and is worth nothing: kappa says so.
TEST(WritingCrossHand, KappaGivesNothingForAgreementThatOneSkillEverywhereMakes) {
  const TimeHeuristicExtractor one_skill(1);
  const std::vector<std::string> words = writing::classic_words(5, 3);
  const CrossHandConsistency other =
      cross_hand_consistency(one_skill, cross_hand_glyphs(), words, 3, {training_drawers()}).front();
  EXPECT_EQ(other.agreeing, other.steps);
  EXPECT_EQ(other.kappa(), 0.0);
  const TimeHeuristicExtractor slices(8);
  const CrossHandConsistency sliced =
      cross_hand_consistency(slices, cross_hand_glyphs(), words, 3, {training_drawers()}).front();
  EXPECT_GT(sliced.kappa(), 0.0);
  EXPECT_LT(sliced.kappa(), sliced.share());
}

TEST(WritingCrossHand, KappaCountsTheChanceAgreementOfTheTwoSkillFrequencies) {
  CrossHandConsistency c;
  c.steps = 10;
  c.agreeing = 7;
  c.clean_skills = {{0, 5}, {1, 5}};
  c.copy_skills = {{0, 4}, {1, 4}, {-2, 2}};
  // chance = (5 * 4 + 5 * 4) / 100 = 0.4; kappa = (0.7 - 0.4) / 0.6.
  EXPECT_DOUBLE_EQ(c.kappa(), 0.5);
  EXPECT_EQ(CrossHandConsistency{}.kappa(), 0.0);
}

// Measured with 100 words at seeds 30 / 31 (docs/skills.md): the shipped model 0.839 / 0.847 on drawers 1-10,
// a run of the same recipe at training seed 5 0.738 / 0.713, the two models before copies by other hands
// 0.52-0.56 - the order of their letter->skill agreement on unseen drawers, which needs true boundaries. On these
// 20 words (seed 32), drawers 1-10 / 11-15: shipped 0.815 / 0.729, seed 5 0.700 / 0.520, 333 x 2 0.500 / 0.447,
// 500 x 1 0.475 / 0.446; the bounds lie between the shipped model and the seed-5 run.
TEST(WritingCrossHand, TheShippedModelKeepsOtherHandsOnTheCleanWordsSkills) {
  const CompileExtractor model = CompileExtractor::load(asset_dir() / "models" / "writing.pt", "writing");
  const std::vector<std::string> words = writing::classic_words(20, 32);
  const std::vector<CrossHandConsistency> shipped =
      cross_hand_consistency(model, cross_hand_glyphs(), words, 32, {training_drawers(), unseen_drawers()});
  EXPECT_GT(shipped[0].share(), 0.76);
  EXPECT_GT(shipped[1].share(), 0.65);
}

}  // namespace
}  // namespace sc
