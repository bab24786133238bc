#include "teaching/tasks/writing_kit.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc {
namespace {

const WritingKit& writing_kit() {
  static const WritingKit k(std::make_shared<TimeHeuristicExtractor>(8), "",
                            WritingKitOptions{{}, writing::AlphabetKind::Classic, 6, 5, std::nullopt});
  return k;
}

TEST(WritingKit, PoolHoldsDistinctGoldWordsSegmentedTwice) {
  ASSERT_EQ(writing_kit().expert_pool().size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const ExpertDemo& d = writing_kit().expert_pool()[i];
    EXPECT_EQ(d.steps.length(), static_cast<int>(writing_kit().gold_words()[i].steps.size()));
    EXPECT_EQ(d.time_slices.segments.size(), 8u);  // K = 8
    EXPECT_EQ(d.reward, 0.0);
    EXPECT_EQ(d.trial.at("source"), "expert");
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(d.scenario, writing_kit().expert_pool()[j].scenario);
  }
  const WritingKit again(std::make_shared<TimeHeuristicExtractor>(8), "",
                         WritingKitOptions{{}, writing::AlphabetKind::Classic, 6, 5, std::nullopt});
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(again.expert_pool()[i].trial, writing_kit().expert_pool()[i].trial);
}

TEST(WritingKit, RewardIsTheOverlapScoreItself) {
  const Json& gold = writing_kit().expert_pool()[0].trial;
  EXPECT_NEAR(writing_kit().reward_of(gold), 0.0, 1e-12);
  // Half the word: recall ~0.5, precision 1 -> about -0.5 (score = recall x precision - 1).
  writing::WritingTrial half = writing::parse_writing_trial(gold, "gold");
  half.points.resize(half.points.size() / 2);
  half.times.clear();
  const double r = writing_kit().reward_of(writing::writing_trial_json(half));
  EXPECT_NEAR(r, -0.5, 0.08);
  // Ink far from the word scores -1 (the bottom of the range).
  writing::WritingTrial far = half;
  for (auto& p : far.points) p.y = std::fmod(p.y + 120.0, 300.0);
  EXPECT_NEAR(writing_kit().reward_of(writing::writing_trial_json(far)), -1.0, 0.05);
}

TEST(WritingKit, FreshScenariosExcludeTheGivenOnesAndRepeatWithTheSeed) {
  const std::vector<Json> first = writing_kit().fresh_scenarios(5, 77, {});
  ASSERT_EQ(first.size(), 5u);
  EXPECT_EQ(writing_kit().fresh_scenarios(5, 77, {}), first);
  const std::vector<Json> fresh = writing_kit().fresh_scenarios(5, 77, {first[1], first[3]});
  ASSERT_EQ(fresh.size(), 5u);
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    EXPECT_NE(fresh[i], first[1]);
    EXPECT_NE(fresh[i], first[3]);
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(fresh[i], fresh[j]);
  }
  // The classic generator has only 60 distinct words.
  EXPECT_LE(writing_kit().fresh_scenarios(100, 1, {}).size(), 60u);
}

TEST(WritingKit, SkillWordsNameCharactersFromTheTrueBoundaries) {
  WordCharacters word{"ab", {0, 10}, 30};
  Segmentation seg{{{0, 0, 3}, {1, 3, 10}, {2, 10, 30}}};
  const auto places = writing_skill_places({word}, {seg}, 3);
  EXPECT_EQ(describe_writing_place(places[0]), "the start of 'a'");
  EXPECT_EQ(describe_writing_place(places[1]), "the middle and end of 'a'");
  EXPECT_DOUBLE_EQ(places[2].share_of('b'), 1.0);
  EXPECT_EQ(describe_writing_place(places[2]), "the letter 'b'");
  // One skill for all of "a", "b" and "-": the letters first, most steps first.
  WordCharacters three{"ab-", {0, 10, 40}, 44};
  const auto merged = writing_skill_places({three}, {Segmentation{{{0, 0, 44}}}}, 1);
  EXPECT_EQ(describe_writing_place(merged[0]), "the letters 'b' and 'a'");  // '-' is under 20 % of the skill
  WordCharacters tail{"a-", {0, 10}, 20};
  EXPECT_EQ(describe_writing_place(writing_skill_places({tail}, {Segmentation{{{0, 0, 20}}}}, 1)[0]),
            "the letter 'a' and the connector '-'");
  // Two skills drawing '-' (the second on more words): distinct names, the more used first; unused skills
  // keep their words.
  WordCharacters dashes{"-", {0}, 20};
  const auto two =
      writing_skill_places({dashes, dashes, dashes},
                           {Segmentation{{{0, 0, 20}}}, Segmentation{{{1, 0, 20}}}, Segmentation{{{1, 0, 20}}}}, 3);
  EXPECT_EQ(describe_writing_places(two), (std::vector<std::string>{"the connector '-', form 2 of 2",
                                                                    "the connector '-', form 1 of 2", "unused skill"}));
  EXPECT_EQ(describe_writing_place(WritingSkillPlace{}), "unused skill");
  for (int m = 0; m < 8; ++m) EXPECT_NE(writing_kit().describe_skill(m), "unused skill");
}

TEST(WritingKit, TimeLimitIsProportionalToTheGoldLength) {
  EXPECT_DOUBLE_EQ(writing_kit().time_limit_seconds(2000), 30.0);
  EXPECT_DOUBLE_EQ(writing_kit().time_limit_seconds(10), 3.0);
}

}  // namespace
}  // namespace sc
