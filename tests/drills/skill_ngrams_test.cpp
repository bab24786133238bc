#include "teaching/drills/skill_ngrams.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

Segmentation seq(const std::vector<int>& skills) { return test::segments_of(skills, 5); }

TEST(SkillNgramTable, CountsConsecutiveSkillsOverAllExpertSequences) {
  const SkillNgramTable table({seq({1, 2, 3, 4}), seq({1, 2, 3}), seq({2, 3, 4}), seq({5, 2, 3})}, 3);
  ASSERT_EQ(table.grams().size(), 3u);
  EXPECT_EQ(table.grams()[0], (SkillNgram{{1, 2, 3}, 2}));  // count 2, lexicographically first
  EXPECT_EQ(table.grams()[1], (SkillNgram{{2, 3, 4}, 2}));
  EXPECT_EQ(table.grams()[2], (SkillNgram{{5, 2, 3}, 1}));
  EXPECT_EQ(table.frequency({2, 3, 4}), 2);
  EXPECT_EQ(table.frequency({3, 4, 5}), 0);
}

TEST(SkillNgramTable, MostFrequentContainingTheTarget) {
  const SkillNgramTable table(
      {seq({1, 2, 3, 4}), seq({1, 2, 3}), seq({2, 3, 4}), seq({5, 2, 3}), seq({5, 2, 3}), seq({5, 2, 3})}, 3);
  EXPECT_EQ(table.most_frequent_containing(4, 1), (std::vector<SkillNgram>{{{2, 3, 4}, 2}}));
  EXPECT_EQ(table.most_frequent_containing(2, 1), (std::vector<SkillNgram>{{{5, 2, 3}, 3}}));
  EXPECT_EQ(table.most_frequent_containing(2, 2).size(), 2u);
  EXPECT_EQ(table.most_frequent_containing(2, 2)[1].skills, (std::vector<int>{1, 2, 3}));
  EXPECT_TRUE(table.most_frequent_containing(9, 3).empty());
  // skip passes over an n-gram already used.
  EXPECT_EQ(table.most_frequent_containing(2, 1, {{5, 2, 3}})[0].skills, (std::vector<int>{1, 2, 3}));
}

TEST(SkillNgramTable, ShortSequencesContributeThemselves) {
  const SkillNgramTable table({seq({7, 8}), seq({7, 8, 9}), seq({}), seq({6})}, 3);
  EXPECT_EQ(table.frequency({7, 8}), 1);
  EXPECT_EQ(table.frequency({6}), 1);
  // Equal counts: the full-length n-gram comes before the shorter grams.
  EXPECT_EQ(table.grams()[0].skills, (std::vector<int>{7, 8, 9}));
  EXPECT_EQ(table.most_frequent_containing(8, 1)[0].skills, (std::vector<int>{7, 8, 9}));
}

TEST(SkillNgramTable, RepeatedSkillsAndUnigrams) {
  const SkillNgramTable bigrams({seq({3, 3, 3})}, 2);
  EXPECT_EQ(bigrams.frequency({3, 3}), 2);
  const SkillNgramTable unigrams({seq({1, 2, 1})}, 1);
  EXPECT_EQ(unigrams.grams()[0], (SkillNgram{{1}, 2}));
  EXPECT_THROW(SkillNgramTable({seq({1})}, 0), InputError);
}

}  // namespace
}  // namespace sc
