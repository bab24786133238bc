// The appendix curve on a small kit: one point per checkpoint read off one training run, the first point
// the untouched student, the expert's level on the same scenarios; bad checkpoint lists are refused.
#include "teaching/students/learning_curve.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/students/bc_datasets.hpp"
#include "teaching/students/expert_drives.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_kit.hpp"

namespace sc {
namespace {

struct Fixture {
  ParkingKit kit;
  FinetuneMaterial material;
  std::vector<ParkingScenario> scenarios;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    ParkingKit kit(std::make_shared<TimeHeuristicExtractor>(kParkingTimeSlices), "",
                   plan_expert_drives(8, 1, GoalRegion::WholeLot));
    ExpertiseEstimate diagnosis;
    diagnosis.expertise = {-1.0, -0.5, -0.2};
    diagnosis.occurrences = {8, 8, 8};
    rank_expertise(diagnosis, 3);
    FinetuneMaterial material{demo_steps(kit.expert_pool()), demo_skills(kit.expert_pool()), diagnosis, 3};
    std::vector<ParkingScenario> scenarios;
    for (int i = 0; i < 4; ++i) scenarios.push_back(parking_pool_scenario(2, i, GoalRegion::WholeLot));
    return Fixture{std::move(kit), std::move(material), std::move(scenarios)};
  }();
  return f;
}

TEST(LearningCurve, OnePointPerCheckpointStartingFromTheUntouchedStudent) {
  const Fixture& f = fixture();
  const BcPolicy student(12, 2, 16, 5);
  LearningCurveConfig config;
  config.checkpoints = {0, 2, 5};
  config.rollouts = 3;
  const LearningCurve curve = fixed_drill_learning_curve(student, BcDataset{}, f.material, f.scenarios, config);
  ASSERT_EQ(curve.points.size(), 3u);
  EXPECT_EQ(curve.points[0].epochs, 0);
  EXPECT_EQ(curve.points[2].epochs, 5);
  const std::vector<ParkingScenario> used(f.scenarios.begin(), f.scenarios.begin() + 3);
  EXPECT_DOUBLE_EQ(curve.points[0].score.mean_reward, score_parking_student(student, used).mean_reward);
  EXPECT_NE(curve.points[2].score.mean_reward, curve.points[0].score.mean_reward);
  EXPECT_GT(curve.points[1].loss, 0.0);
  EXPECT_GT(curve.drill_pairs, 0);
  EXPECT_EQ(curve.rehearsal_pairs, 0);
  EXPECT_GT(curve.expert.success_rate, 0.5);
  // The student itself is not changed, and the same config gives the same curve.
  EXPECT_DOUBLE_EQ(score_parking_student(student, used).mean_reward, curve.points[0].score.mean_reward);
  const LearningCurve again = fixed_drill_learning_curve(student, BcDataset{}, f.material, f.scenarios, config);
  EXPECT_EQ(again.points[2].score.mean_reward, curve.points[2].score.mean_reward);
}

TEST(LearningCurve, RefusesBadCheckpointsAndTooFewScenarios) {
  const Fixture& f = fixture();
  const BcPolicy student(12, 2, 16, 5);
  LearningCurveConfig config;
  config.rollouts = 3;
  for (std::vector<int> bad : {std::vector<int>{}, std::vector<int>{5, 2}, std::vector<int>{-1, 3}}) {
    config.checkpoints = bad;
    EXPECT_THROW(fixed_drill_learning_curve(student, BcDataset{}, f.material, f.scenarios, config), InputError);
  }
  config.checkpoints = {0, 1};
  config.rollouts = 10;
  EXPECT_THROW(fixed_drill_learning_curve(student, BcDataset{}, f.material, f.scenarios, config), InputError);
}

}  // namespace
}  // namespace sc
