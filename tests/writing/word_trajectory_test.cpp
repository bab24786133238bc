#include "engine/writing/word_trajectory.hpp"

#include <algorithm>
#include <limits>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/word_generator.hpp"

namespace sc::writing {
namespace {

struct Extent {
  double max_x = -1e9, min_y = 1e9, max_y = -1e9, min_x = 1e9;
};
Extent extent_of(const WordTrajectory& w) {
  Extent e;
  for (const auto& p : w.points()) {
    e.max_x = std::max(e.max_x, p.x), e.min_x = std::min(e.min_x, p.x);
    e.min_y = std::min(e.min_y, p.y), e.max_y = std::max(e.max_y, p.y);
  }
  return e;
}

class ClassicWords : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { glyphs_ = new GlyphSet(GlyphSet::load(AlphabetKind::Classic, omniglot_data_dir())); }
  static void TearDownTestSuite() { delete glyphs_; }
  static const GlyphSet* glyphs_;
};
const GlyphSet* ClassicWords::glyphs_ = nullptr;

TEST_F(ClassicWords, ChainsGlyphsFromTheStart) {
  const auto w = build_word_trajectory(*glyphs_, "ab-c");
  EXPECT_EQ(w.steps.size(), 724u + 409u + 20u + 635u);
  EXPECT_EQ(w.character_starts, (std::vector<int>{0, 724, 1133, 1153}));
  EXPECT_EQ(w.goal, (std::vector<int>{0, 1, 5, 2, -1, -1, -1, -1, -1, -1}));
  const auto pts = w.points();
  ASSERT_EQ(pts.size(), w.steps.size() + 1);
  EXPECT_EQ(pts[0].x, 0.0);
  EXPECT_EQ(pts[0].y, 150.0);
  // The '-' starts where 'b' ended and is a 20 px horizontal line.
  EXPECT_EQ(pts[1153].x - pts[1133].x, 20.0);
  EXPECT_EQ(pts[1153].y, pts[1133].y);
  for (const auto& p : pts) EXPECT_TRUE(p.pen);
}

TEST_F(ClassicWords, AllTrainingWordsFitTheCanvasAsInTheReference) {
  // Every sixgram+bigram / bigram+sixgram word (reference §2.5: x reaches 316-475 px, y in [66.6, 183.6]).
  double lowest_reach = 1e9, highest_reach = -1e9, min_y = 1e9, max_y = -1e9;
  for (const auto& six : classic_sixgrams())
    for (const auto& two : classic_bigrams())
      for (const std::string& word :
           {std::string(six.text) + std::string(two.text), std::string(two.text) + std::string(six.text)}) {
        const Extent e = extent_of(build_word_trajectory(*glyphs_, word));
        lowest_reach = std::min(lowest_reach, e.max_x), highest_reach = std::max(highest_reach, e.max_x);
        min_y = std::min(min_y, e.min_y), max_y = std::max(max_y, e.max_y);
      }
  EXPECT_NEAR(lowest_reach, 316, 0.5);
  EXPECT_NEAR(highest_reach, 475, 0.5);
  EXPECT_NEAR(min_y, 66.6, 0.05);
  EXPECT_NEAR(max_y, 183.6, 0.05);
}

TEST_F(ClassicWords, RejectsBadWords) {
  EXPECT_THROW(build_word_trajectory(*glyphs_, ""), InputError);
  EXPECT_THROW(build_word_trajectory(*glyphs_, "abcabcabcab"), InputError);  // 11 > 10 symbols
  try {
    validate_word(AlphabetKind::Classic, "ax", "trial.json: $.scenario.word");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "trial.json: $.scenario.word: 'x' is not a symbol of the classic alphabet (valid: abcte-^)");
  }
}

TEST(BalineseWords, DrawersChangeTheGlyphAndWordsFitTheCanvas) {
  const auto data = omniglot_data_dir();
  const GlyphSet defaults = GlyphSet::load(AlphabetKind::Balinese, data);
  const GlyphSet chosen = GlyphSet::load(AlphabetKind::Balinese, data, {{'B', 7}});
  EXPECT_EQ(defaults.drawers().at('B'), 4);  // the paper's drawer for 'a' = character02
  EXPECT_EQ(defaults.drawers().at('A'), 1);
  EXPECT_EQ(chosen.drawers().at('B'), 7);
  EXPECT_EQ(chosen.glyph('B').source, "character02/0109_07.txt");
  EXPECT_NE(chosen.glyph('B').steps, defaults.glyph('B').steps);
  EXPECT_EQ(chosen.glyph('C').steps, defaults.glyph('C').steps);

  Rng rng(11);
  for (int i = 0; i < 100; ++i) {
    const std::string word = generate_balinese_word(rng);
    const auto w = build_word_trajectory(defaults, word);
    ASSERT_EQ(w.character_starts.size(), word.size());
    const Extent e = extent_of(w);
    EXPECT_GE(e.min_x, 0.0) << word;
    EXPECT_LE(e.max_x, kCanvasWidth) << word;
    EXPECT_GE(e.min_y, 0.0) << word;
    EXPECT_LE(e.max_y, kCanvasHeight) << word;
  }
}

TEST(BalineseWords, DrawerErrors) {
  const auto data = omniglot_data_dir();
  EXPECT_THROW(GlyphSet::load(AlphabetKind::Balinese, data, {{'B', 16}}), InputError);
  EXPECT_THROW(GlyphSet::load(AlphabetKind::Balinese, data, {{'-', 1}}), InputError);
  EXPECT_THROW(GlyphSet::load(AlphabetKind::Classic, data, {{'a', 1}}), InputError);
  EXPECT_THROW(GlyphSet::load(AlphabetKind::Balinese, "/nonexistent"), InputError);
}

}  // namespace
}  // namespace sc::writing
