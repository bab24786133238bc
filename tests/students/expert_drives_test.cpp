// The students' own expert drives: planned to success; and the MSE split by
// the expert's acceleration sign, which is how the reversing student's deficit is measured.
#include "teaching/students/expert_drives.hpp"

#include <gtest/gtest.h>

#include "teaching/students/bc_datasets.hpp"

namespace sc {
namespace {

TEST(ExpertDrives, PlansParkAndGiveOnePairPerStep) {
  int ticks = 0;
  const std::vector<ParkingTrial> drives =
      plan_expert_drives(3, 9, GoalRegion::WholeLot, [&](int done) { ticks = done; });
  ASSERT_EQ(drives.size(), 3u);
  EXPECT_EQ(ticks, 3);
  std::size_t steps = 0;
  for (const ParkingTrial& t : drives) {
    EXPECT_TRUE(t.success.value_or(false));
    steps += t.actions.size();
  }
  const BcDataset pairs = bc_dataset_from_trials(drives);
  EXPECT_EQ(static_cast<std::size_t>(pairs.size()), steps);
  EXPECT_EQ(pairs.state_dim, 12);
  EXPECT_EQ(pairs.action_dim, 2);
}

TEST(ExpertDrives, SplitMseWeighsTheTwoSignsByTheirCounts) {
  BcDataset data;
  data.state_dim = 2;
  data.action_dim = 2;
  data.states = {0.1f, 0.2f, -0.3f, 0.4f, 0.5f, -0.6f, 0.7f, 0.8f, -0.9f, 0.0f};
  data.actions = {-0.8f, 0.1f, 0.6f, -0.2f, -0.4f, 0.3f, 0.9f, 0.0f, 0.2f, 0.5f};
  const BcPolicy policy(2, 2, 8, 1);
  const SplitMse mse = split_mse(policy, data);
  const int reverse = count_reverse_pairs(data);
  ASSERT_EQ(reverse, 2);
  EXPECT_NEAR(mse.all, (reverse * mse.reverse + (data.size() - reverse) * mse.forward) / data.size(), 1e-6);
  EXPECT_NE(mse.reverse, mse.forward);
}

}  // namespace
}  // namespace sc
