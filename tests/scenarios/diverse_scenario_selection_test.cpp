#include "teaching/scenarios/diverse_scenario_selection.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

// An expert segmentation with the given skill sequence, 4 steps per segment.
Segmentation seq(const std::vector<int>& skills) { return test::segments_of(skills, 4); }

TEST(DiverseScenarioSelection, GreedyPicksTheCoveringSet) {
  // 1 covers three skills, then 2 adds {3,4}, then 4 adds {5}: all six skills with three scenarios.
  const std::vector<Segmentation> pool = {seq({0, 1}), seq({0, 1, 2}), seq({3, 4}), seq({2, 3}), seq({5})};
  const ScenarioSelection sel = select_diverse_scenarios(pool, 3);
  EXPECT_EQ(sel.scenarios(), (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(sel.covered_skills, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(sel.picks[0].new_skills, 3);
  EXPECT_EQ(sel.picks[1].new_skills, 2);
  EXPECT_EQ(sel.picks[2].new_skills, 1);
}

TEST(DiverseScenarioSelection, TiesGoToTheLowestIndex) {
  const std::vector<Segmentation> pool = {seq({7, 8}), seq({7, 8}), seq({8, 7})};
  // 0 and 2 tie on skills and bigrams; 0 wins by index. Then 2 adds the new bigram (8,7), 1 adds none.
  EXPECT_EQ(select_diverse_scenarios(pool, 3).scenarios(), (std::vector<int>{0, 2, 1}));
}

TEST(DiverseScenarioSelection, AfterFullCoverageNewBigramsThenLeastRedundancy) {
  const std::vector<Segmentation> pool = {seq({0, 1, 2}), seq({0, 1, 2}), seq({0, 1}), seq({2, 1, 0})};
  const ScenarioSelection sel = select_diverse_scenarios(pool, 4);
  // 0 first (3 skills, lowest index). Every skill is then covered: 3 adds two new bigrams (2,1),(1,0).
  // Then 1 (skills shown 2+2+2 = 6 times before) vs 2 (2+2 = 4): 2 is less redundant.
  EXPECT_EQ(sel.scenarios(), (std::vector<int>{0, 3, 2, 1}));
  EXPECT_EQ(sel.picks[1].new_skills, 0);
  EXPECT_EQ(sel.picks[1].new_bigrams, 2);
  EXPECT_EQ(sel.picks[2].redundancy, 4);
  EXPECT_EQ(sel.picks[3].redundancy, 8);  // 3 + 3 + 2
}

TEST(DiverseScenarioSelection, CountIsClampedAndValidated) {
  const std::vector<Segmentation> pool = {seq({0}), Segmentation{}, seq({1})};
  EXPECT_EQ(select_diverse_scenarios(pool, 10).scenarios(), (std::vector<int>{0, 2, 1}));
  EXPECT_TRUE(select_diverse_scenarios(pool, 0).picks.empty());
  EXPECT_TRUE(select_diverse_scenarios({}, 5).picks.empty());
  EXPECT_THROW(select_diverse_scenarios(pool, -1), InputError);
}

TEST(DiverseScenarioSelection, DeterministicAndCoverageNeverShrinks) {
  Rng rng(42);
  std::vector<Segmentation> pool;
  for (int i = 0; i < 200; ++i) {
    std::vector<int> skills;
    const int len = 1 + static_cast<int>(rng.below(4));
    for (int k = 0; k < len; ++k) skills.push_back(static_cast<int>(rng.below(16)));
    pool.push_back(seq(skills));
  }
  const ScenarioSelection a = select_diverse_scenarios(pool, 25);
  const ScenarioSelection b = select_diverse_scenarios(pool, 25);
  ASSERT_EQ(a.picks.size(), 25u);
  EXPECT_EQ(a.picks, b.picks);
  // Greedy gains never increase, and the picks cover every skill that occurs in the pool.
  for (std::size_t i = 1; i < a.picks.size(); ++i) EXPECT_LE(a.picks[i].new_skills, a.picks[i - 1].new_skills);
  EXPECT_EQ(a.covered_skills.size(), 16u);
}

}  // namespace
}  // namespace sc
