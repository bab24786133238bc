#include "teaching/students/bc_datasets.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

// n pairs with 1-D states s = i and 2-D actions (u0, u1) = (+-1, i): every third pair reverses.
BcDataset toy_pairs(int n) {
  BcDataset d;
  d.state_dim = 1;
  d.action_dim = 2;
  for (int i = 0; i < n; ++i) {
    d.states.push_back(static_cast<float>(i));
    d.actions.push_back(i % 3 == 0 ? -0.5f : 0.5f);
    d.actions.push_back(static_cast<float>(i));
  }
  return d;
}

std::vector<int> kept_reverse_ids(const BcDataset& d) {
  std::vector<int> ids;
  for (int i = 0; i < d.size(); ++i)
    if (d.actions[static_cast<std::size_t>(2 * i)] < 0)
      ids.push_back(static_cast<int>(d.states[static_cast<std::size_t>(i)]));
  return ids;
}

TEST(BcDatasets, ReverseFilterKeepsTwentyPercentOfReversePairsAndEveryOtherPair) {
  const BcDataset all = toy_pairs(300);  // 100 reverse pairs, 200 forward
  ASSERT_EQ(count_reverse_pairs(all), 100);
  const BcDataset kept = keep_reverse_fraction(all, 0.2, 7);
  EXPECT_EQ(count_reverse_pairs(kept), 20);
  EXPECT_EQ(kept.size(), 220);
  // Original order kept, and every pair is an unchanged copy of one of the originals.
  for (int i = 1; i < kept.size(); ++i)
    EXPECT_LT(kept.states[static_cast<std::size_t>(i - 1)], kept.states[static_cast<std::size_t>(i)]);
  for (int i = 0; i < kept.size(); ++i) {
    const int id = static_cast<int>(kept.states[static_cast<std::size_t>(i)]);
    EXPECT_EQ(kept.actions[static_cast<std::size_t>(2 * i + 1)], static_cast<float>(id));
  }
  // Rounding: 0.2 x 7 = 1.4 -> 1 pair.
  EXPECT_EQ(count_reverse_pairs(keep_reverse_fraction(toy_pairs(21), 0.2, 7)), 1);
  EXPECT_EQ(count_reverse_pairs(keep_reverse_fraction(all, 1.0, 7)), 100);
  EXPECT_EQ(count_reverse_pairs(keep_reverse_fraction(all, 0.0, 7)), 0);
}

TEST(BcDatasets, ReverseFilterIsDeterministicInItsSeed) {
  const BcDataset all = toy_pairs(300);
  const auto a = kept_reverse_ids(keep_reverse_fraction(all, 0.2, 7));
  EXPECT_EQ(a, kept_reverse_ids(keep_reverse_fraction(all, 0.2, 7)));
  EXPECT_NE(a, kept_reverse_ids(keep_reverse_fraction(all, 0.2, 8)));
  // Not simply the first ones: the sample is spread over the data.
  EXPECT_GT(a.back(), 150);
}

TEST(BcDatasets, ReverseFilterRefusesFractionsOutsideZeroToOne) {
  EXPECT_THROW(keep_reverse_fraction(toy_pairs(3), 1.5, 0), InputError);
  EXPECT_THROW(keep_reverse_fraction(toy_pairs(3), std::nan(""), 0), InputError);
}

TEST(BcDatasets, PairsFromStepsAndPlansKeepEachSegmentsOwnStates) {
  StepSequence a{1, 2, {0, 1, 2}, {0, 0, 1, 1, 2, 2}};
  StepSequence b{1, 2, {10, 11, 12, 13}, {10, 10, 11, 11, 12, 12, 13, 13}};
  const BcDataset both = bc_dataset_from_steps({a, b});
  EXPECT_EQ(both.size(), 7);
  EXPECT_EQ(both.states[3], 10.0f);
  DrillPlan plan;
  plan.segments = {{4, 1, 2, 4}, {5, 0, 0, 1}};  // b[2..4) then a[0..1)
  const BcDataset p = bc_dataset_from_plan(plan, {a, b});
  ASSERT_EQ(p.size(), 3);
  EXPECT_EQ(p.states, (std::vector<float>{12, 13, 0}));
  EXPECT_EQ(p.actions, (std::vector<float>{12, 12, 13, 13, 0, 0}));
  StepSequence wide{2, 2, {0, 0}, {0, 0}};
  EXPECT_THROW(bc_dataset_from_steps({a, wide}), InputError);
}

TEST(BcDatasets, FirstPairsCutsToAnExactSize) {
  const BcDataset all = toy_pairs(10);
  const BcDataset four = first_pairs(all, 4);
  EXPECT_EQ(four.size(), 4);
  EXPECT_EQ(four.states, (std::vector<float>{0, 1, 2, 3}));
  EXPECT_EQ(first_pairs(all, 50).size(), 10);
}

TEST(BcDatasets, SamplePairsDrawsDistinctPairsInOrderDeterministically) {
  const BcDataset all = toy_pairs(40);
  const BcDataset a = sample_pairs(all, 10, 7);
  ASSERT_EQ(a.size(), 10);
  for (int i = 1; i < a.size(); ++i)
    EXPECT_LT(a.states[static_cast<std::size_t>(i - 1)], a.states[static_cast<std::size_t>(i)]);
  for (int i = 0; i < a.size(); ++i)  // each drawn pair is whole: its action belongs to its state
    EXPECT_EQ(a.actions[static_cast<std::size_t>(2 * i + 1)], a.states[static_cast<std::size_t>(i)]);
  EXPECT_EQ(sample_pairs(all, 10, 7).states, a.states);
  EXPECT_NE(sample_pairs(all, 10, 8).states, a.states);
  EXPECT_NE(a.states, first_pairs(all, 10).states);  // not just the first ones
  EXPECT_EQ(sample_pairs(all, 99, 7).states, all.states);
  EXPECT_EQ(sample_pairs(all, 0, 7).size(), 0);
}

}  // namespace
}  // namespace sc
