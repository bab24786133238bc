#include "teaching/tasks/writing_planted_weakness.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace sc {
namespace {

const ClassicDrawerGlyphs& classic_glyphs() {
  static const ClassicDrawerGlyphs g = ClassicDrawerGlyphs::load();
  return g;
}

// The same learner (seed) with and without its fault: the trace is identical until the faulty letter.
std::size_t common_prefix(const writing::WritingTrial& a, const writing::WritingTrial& b) {
  std::size_t n = 0;
  while (n < std::min(a.points.size(), b.points.size()) && a.points[n] == b.points[n]) ++n;
  return n;
}

TEST(WritingPlantedWeakness, EachFaultChangesItsLetterOnly) {
  const std::string word = "ct-b^e";  // 'b' starts after c, t and '-'
  const writing::WritingTrial plain = planted_trial(classic_glyphs(), word, {'b', LetterFault::None, 4}, 0);
  EXPECT_EQ(plain.points, planted_trial(classic_glyphs(), word, {'b', LetterFault::None, 4}, 0).points);  // seeded
  EXPECT_EQ(plain.scenario.word, word);
  for (LetterFault fault : {LetterFault::Distorted, LetterFault::OtherDrawer, LetterFault::StraightLine}) {
    const writing::WritingTrial bad = planted_trial(classic_glyphs(), word, {'b', fault, 4}, 0);
    const std::size_t same = common_prefix(plain, bad);
    EXPECT_LT(same, bad.points.size()) << to_string(fault);
    // c, t and '-' come before 'b': about half the word's ink, so well over a third of the points agree.
    EXPECT_GT(same, plain.points.size() / 3) << to_string(fault);
  }
  // A letter the word does not contain leaves the trace as it is.
  EXPECT_EQ(planted_trial(classic_glyphs(), word, {'a', LetterFault::StraightLine, 4}, 0).points,
            planted_trial(classic_glyphs(), word, {'a', LetterFault::None, 4}, 0).points);
}

TEST(WritingPlantedWeakness, AnOwnHandWritesEveryLetterInAnUnseenDrawersShape) {
  const std::string word = "ct-b^e";
  const std::vector<int> unseen = unseen_drawers();
  PlantedLearner own{'b', LetterFault::OtherDrawer, 4};
  own.hand_drawer = own_hand_drawer(own);
  EXPECT_NE(std::find(unseen.begin(), unseen.end(), own.hand_drawer), unseen.end()) << own.hand_drawer;
  EXPECT_EQ(own_hand_drawer(own), own.hand_drawer);  // drawn from the learner's seed
  const writing::WritingTrial paper = planted_trial(classic_glyphs(), word, {'b', LetterFault::OtherDrawer, 4}, 0);
  const writing::WritingTrial mine = planted_trial(classic_glyphs(), word, own, 0);
  EXPECT_LT(common_prefix(paper, mine), paper.points.size() / 10);  // the first letter is already another shape
  // The fault still changes its letter only: the same hand without it agrees until the 'b'.
  PlantedLearner plain = own;
  plain.fault = LetterFault::None;
  const std::size_t same = common_prefix(planted_trial(classic_glyphs(), word, plain, 0), mine);
  EXPECT_GT(same, 5u);
  EXPECT_LT(same, mine.points.size());
}

// Measured with the shipped glyphs (docs/skills.md, "Copies by other hands"): drawer 14's `a` scores -0.33
// against the paper's `a`, drawer 3's -0.79 - the first is found far less often as a fault.
TEST(WritingPlantedWeakness, TheOtherDrawerShapeScoreSaysHowFarALetterIsFromTheExperts) {
  const int paper_a = writing::default_drawer(writing::AlphabetKind::Classic, 'a');
  EXPECT_DOUBLE_EQ(other_drawer_shape_score(classic_glyphs(), 'a', 0), 0.0);
  EXPECT_DOUBLE_EQ(other_drawer_shape_score(classic_glyphs(), 'a', paper_a), 0.0);
  for (char letter : std::string("abcte"))
    for (int drawer = 1; drawer <= writing::kDrawersPerCharacter; ++drawer) {
      const double score = other_drawer_shape_score(classic_glyphs(), letter, drawer);
      EXPECT_GE(score, -1.0) << letter << drawer;
      EXPECT_LE(score, 0.0) << letter << drawer;
    }
  EXPECT_GT(other_drawer_shape_score(classic_glyphs(), 'a', 14), -0.45);
  EXPECT_LT(other_drawer_shape_score(classic_glyphs(), 'a', 3), -0.7);
}

}  // namespace
}  // namespace sc
