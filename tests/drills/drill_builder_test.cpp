#include "teaching/drills/drill_builder.hpp"

#include <set>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

// Segmentation from (skill, length) pairs laid end to end.
Segmentation seq(const std::vector<std::pair<int, int>>& parts) { return test::segments_of(parts); }

// A pool where (0,1,2) is the most frequent 3-gram containing 1, and skill 1 has many distinct segments.
std::vector<Segmentation> pool() {
  std::vector<Segmentation> p;
  for (int i = 0; i < 6; ++i) p.push_back(seq({{0, 4 + i}, {1, 5 + i}, {2, 3}}));
  p.push_back(seq({{3, 4}, {1, 2}, {4, 6}}));
  p.push_back(seq({{3, 4}, {1, 2}, {4, 6}, {5, 1}}));
  p.push_back(seq({{5, 3}, {6, 2}}));
  return p;
}

ExpertiseEstimate weakest_first(const std::vector<int>& ranking) {
  ExpertiseEstimate e;
  e.ranking = ranking;
  return e;
}

TEST(DrillBuilder, PresetsAreThePapersValues) {
  const DrillConfig p = DrillConfig::parking();
  EXPECT_EQ(std::vector<int>({p.ngram_length, p.repetitions, p.num_targets, p.drills_per_target}),
            std::vector<int>({3, 1, 7, 1}));
  const DrillConfig w = DrillConfig::writing();
  EXPECT_EQ(std::vector<int>({w.ngram_length, w.repetitions, w.num_targets, w.drills_per_target}),
            std::vector<int>({2, 3, 8, 1}));
  DrillConfig bad = p;
  bad.repetitions = 0;
  EXPECT_THROW(DrillBuilder(pool(), bad), InputError);
}

TEST(DrillBuilder, DrillsTheMostFrequentNgramWithExpertSegmentsOfEachSkill) {
  const std::vector<Segmentation> experts = pool();
  const DrillBuilder builder(experts, DrillConfig::parking());
  Rng rng(1);
  const std::vector<DrillPlan> drills = builder.for_targets({1}, rng);
  ASSERT_EQ(drills.size(), 1u);
  const DrillPlan& d = drills[0];
  EXPECT_EQ(d.target_skill, 1);
  EXPECT_EQ(d.ngram, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(d.ngram_count, 6);
  EXPECT_EQ(d.skills(), d.ngram);
  for (const DrillSegment& s : d.segments) {
    // Every segment is a real expert segment of its skill.
    const auto& segs = experts[static_cast<std::size_t>(s.expert)].segments;
    EXPECT_NE(std::find(segs.begin(), segs.end(), SkillSegment{s.skill, s.begin, s.end}), segs.end());
  }
}

TEST(DrillBuilder, RepeatsTheSameSegmentsNrepTimes) {
  DrillConfig config = DrillConfig::writing();  // n = 2, N_rep = 3
  const DrillBuilder builder(pool(), config);
  Rng rng(5);
  const DrillPlan d = builder.for_targets({4}, rng).at(0);
  EXPECT_EQ(d.ngram, (std::vector<int>{1, 4}));  // (1,4) twice beats (4,5) once
  EXPECT_EQ(d.repetitions, 3);
  ASSERT_EQ(d.segments.size(), 6u);
  for (std::size_t i = 2; i < 6; ++i) EXPECT_EQ(d.segments[i], d.segments[i - 2]);
  EXPECT_EQ(d.length(), 3 * (d.segments[0].length() + d.segments[1].length()));
}

TEST(DrillBuilder, SegmentChoiceIsSeededDeterministicAndVariesWithTheSeed) {
  const DrillBuilder builder(pool(), DrillConfig::parking());
  std::set<std::vector<int>> choices;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    Rng a(seed), b(seed);
    const DrillPlan da = builder.for_targets({1}, a).at(0);
    EXPECT_EQ(da, builder.for_targets({1}, b).at(0)) << seed;
    std::vector<int> experts;
    for (const auto& s : da.segments) experts.push_back(s.expert);
    choices.insert(experts);
  }
  EXPECT_GT(choices.size(), 5u);  // 6^3 combinations of experts; 20 seeds give many distinct ones
}

TEST(DrillBuilder, IndividualizedTargetsTheWeakestSkillsAndKeepsNgramsDistinct) {
  DrillConfig config = DrillConfig::parking();
  config.num_targets = 2;
  Rng rng(3);
  // 0 and 1 share the most frequent n-gram (0,1,2): 0 (weaker) gets it, 1 takes its next one, (3,1,4).
  const auto drills = DrillBuilder(pool(), config).individualized(weakest_first({0, 1, 2, 3}), rng);
  ASSERT_EQ(drills.size(), 2u);
  EXPECT_EQ(drills[0].target_skill, 0);
  EXPECT_EQ(drills[0].ngram, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(drills[1].target_skill, 1);
  EXPECT_EQ(drills[1].ngram, (std::vector<int>{3, 1, 4}));

  config.distinct_ngrams = false;  // the paper's literal Alg. 3
  Rng rng2(3);
  const auto literal = DrillBuilder(pool(), config).individualized(weakest_first({0, 1}), rng2);
  EXPECT_EQ(literal[1].ngram, (std::vector<int>{0, 1, 2}));

  config.distinct_ngrams = true;
  Rng rng3(3);
  const auto fallback = DrillBuilder(pool(), config).individualized(weakest_first({0, 2}), rng3);
  EXPECT_EQ(fallback[1].ngram, (std::vector<int>{0, 1, 2}));  // 2 has no other n-gram
}

TEST(DrillBuilder, ATargetWithFewerUnusedNgramsThanDrillsStillGetsItsDrills) {
  DrillConfig config = DrillConfig::parking();
  config.drills_per_target = 2;
  Rng rng(5);
  // Skill 6 occurs in one n-gram only, (5,6): both of its drills use it, cut from fresh segments.
  const auto drills = DrillBuilder(pool(), config).for_targets({6}, rng);
  ASSERT_EQ(drills.size(), 2u);
  EXPECT_EQ(drills[0].ngram, (std::vector<int>{5, 6}));
  EXPECT_EQ(drills[1].ngram, (std::vector<int>{5, 6}));
  // Skill 0 occurs in (0,1,2) only: both its drills; skill 1 then takes its two n-grams still unused.
  Rng rng2(5);
  const auto shared = DrillBuilder(pool(), config).for_targets({0, 1}, rng2);
  ASSERT_EQ(shared.size(), 4u);
  EXPECT_EQ(shared[1].ngram, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(shared[2].ngram, (std::vector<int>{3, 1, 4}));
  EXPECT_EQ(shared[3].ngram, (std::vector<int>{1, 4, 5}));
  config.distinct_ngrams = false;  // literal: only the n-grams there are
  Rng rng3(5);
  EXPECT_EQ(DrillBuilder(pool(), config).for_targets({6}, rng3).size(), 1u);
}

TEST(DrillBuilder, TargetsAbsentFromThePoolGetNoDrill) {
  Rng rng(0);
  const auto drills = DrillBuilder(pool(), DrillConfig::parking()).for_targets({42, 6}, rng);
  ASSERT_EQ(drills.size(), 1u);
  EXPECT_EQ(drills[0].ngram, (std::vector<int>{5, 6}));  // short expert sequence kept as a gram
}

TEST(DrillBuilder, PrefersSegmentsOfTheMinimumLength) {
  DrillConfig config = DrillConfig::parking();
  config.min_segment_length = 2;
  const DrillBuilder builder(pool(), config);
  for (std::uint64_t seed = 0; seed < 30; ++seed) {
    Rng rng(seed);
    EXPECT_GE(builder.random_segment(5, rng).length(), 2);  // skill 5 has one 1-step and one 3-step segment
  }
  Rng rng(0);
  EXPECT_THROW(builder.random_segment(42, rng), InputError);
}

TEST(DrillBuilder, RandomDrillsComeFromTheOfflineSetWithoutReplacement) {
  const DrillBuilder builder(pool(), DrillConfig::parking());
  const std::vector<SkillNgram> offline = builder.offline_ngrams();
  // One most-frequent n-gram per skill 0..6, duplicates removed.
  EXPECT_EQ(offline.size(), 4u);  // (0,1,2) for 0,1,2; (3,1,4) for 3,4; (1,4,5) for 5; (5,6) for 6
  Rng a(9), b(9);
  const auto drills = builder.random_drills(4, a);
  EXPECT_EQ(drills, builder.random_drills(4, b));
  std::set<std::vector<int>> distinct;
  for (const auto& d : drills) {
    EXPECT_EQ(d.target_skill, -1);
    distinct.insert(d.ngram);
  }
  EXPECT_EQ(distinct.size(), 4u);
  EXPECT_EQ(builder.random_drills(9, a).size(), 9u);
}

}  // namespace
}  // namespace sc
