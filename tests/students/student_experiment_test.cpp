// The synthetic-student protocol end to end on a small parking kit (16 expert demos, time-heuristic skills,
// 12 student drives, tiny networks and epochs): seconds, not minutes. Checks determinism and the protocol's invariants,
// not the paper's findings (docs/students.md has the full run).
#include "teaching/students/student_experiment.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/students/student_report.hpp"
#include "teaching/tasks/parking_kit.hpp"

namespace sc {
namespace {

const ParkingKit& small_kit() {
  static const ParkingKit kit = [] {
    std::vector<ParkingTrial> pool = load_or_generate_parking_pool(default_parking_pool_file(), {}).trials;
    pool.resize(16);
    return ParkingKit(std::make_shared<TimeHeuristicExtractor>(kParkingTimeSlices), "", std::move(pool));
  }();
  return kit;
}

StudentExperimentConfig tiny_config(std::uint64_t seed) {
  StudentExperimentConfig c = StudentExperimentConfig::paper();
  for (SyntheticStudentRecipe& r : c.students) {
    r.epochs = r.kind == SyntheticStudentKind::HalfTrained ? 2 : 4;
    r.hidden = 32;
  }
  c.reference.epochs = 4;
  c.reference.hidden = 32;
  c.student_drives = 12;
  c.heldout_drives = 4;
  c.curve.checkpoints = {0, 2, 3};
  c.curve.rollouts = 3;
  c.seed = seed;
  c.diagnosis_scenarios = 4;
  c.finetune_epochs = 2;
  c.evaluation_sets = 3;
  c.scenarios_per_set = 2;
  return c;
}

TEST(StudentExperiment, PaperConfigurationMatchesTheAppendix) {
  const StudentExperimentConfig c = StudentExperimentConfig::paper();
  ASSERT_EQ(c.students.size(), 2u);
  EXPECT_EQ(c.students[0].kind, SyntheticStudentKind::HalfTrained);
  EXPECT_EQ(c.students[0].epochs, 50);
  EXPECT_EQ(c.students[0].reverse_keep_fraction, 1.0);
  EXPECT_EQ(c.students[1].kind, SyntheticStudentKind::ReversingDifficulty);
  EXPECT_EQ(c.students[1].epochs, 400);
  EXPECT_EQ(c.students[1].reverse_keep_fraction, 0.2);
  EXPECT_EQ(c.diagnosis_scenarios, 25);
  EXPECT_EQ(c.num_targets, 3);
  EXPECT_EQ(c.finetune_epochs, 100);
  EXPECT_EQ(c.evaluation_sets, 15);
  EXPECT_EQ(c.reference.kind, SyntheticStudentKind::FullyTrained);
  EXPECT_EQ(c.reference.epochs, 400);
  EXPECT_EQ(c.reference.reverse_keep_fraction, 1.0);
  EXPECT_EQ(c.curve.rollouts, 100);  // the appendix: "average reward over 100 random rollouts"
}

TEST(StudentExperiment, RunsTheProtocolWithEqualSizeDataForEveryCondition) {
  const StudentExperimentResult r = run_student_experiment(small_kit(), tiny_config(1));
  EXPECT_EQ(r.pool_size, 16);
  EXPECT_EQ(r.diagnosis_scenarios.size(), 4u);
  ASSERT_EQ(r.students.size(), 2u);
  for (const StudentResult& s : r.students) {
    EXPECT_FALSE(s.diagnosis.targets.empty());
    EXPECT_LE(s.diagnosis.targets.size(), 3u);
    EXPECT_EQ(s.before_reward.size(), 3u);
    EXPECT_EQ(s.before_step_reward.size(), 3u);
    EXPECT_GT(s.heldout_mse.all, 0.0);
    EXPECT_GT(s.heldout_mse.reverse, 0.0);
    EXPECT_GT(s.heldout_mse.forward, 0.0);
    ASSERT_EQ(s.conditions.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const int pairs = s.conditions[0].pairs[static_cast<std::size_t>(k)];
      EXPECT_GT(pairs, 0);
      for (const ConditionResult& c : s.conditions) {
        EXPECT_EQ(c.pairs[static_cast<std::size_t>(k)], pairs) << condition_name(c.condition) << " set " << k;
        ASSERT_EQ(c.heldout_mse.size(), 3u);
        EXPECT_GT(c.heldout_mse[static_cast<std::size_t>(k)].reverse, 0.0);
        EXPECT_LE(c.reward[static_cast<std::size_t>(k)], 0.0);
        EXPECT_GE(c.success[static_cast<std::size_t>(k)], 0.0);
        EXPECT_LE(c.success[static_cast<std::size_t>(k)], 1.0);
      }
    }
  }
  // The reversing-difficulty student saw 20 % of the expert's reverse-acceleration pairs, the other all.
  const StudentResult& half = r.students[0];
  const StudentResult& reversing = r.students[1];
  EXPECT_EQ(half.reverse_pairs_kept, half.reverse_pairs_total);
  ASSERT_GT(reversing.reverse_pairs_total, 10);
  EXPECT_EQ(reversing.reverse_pairs_kept, std::lround(0.2 * reversing.reverse_pairs_total));
  // Students learn from their own drives, not from the teaching pool.
  EXPECT_EQ(half.training_pairs, r.student_pairs);
  EXPECT_NE(r.student_pairs, r.expert_pairs);
  EXPECT_EQ(reversing.training_pairs, r.student_pairs - (reversing.reverse_pairs_total - reversing.reverse_pairs_kept));
  // The fully trained yardstick is measured and diagnosed but not fine-tuned.
  EXPECT_EQ(r.reference.recipe.kind, SyntheticStudentKind::FullyTrained);
  EXPECT_TRUE(r.reference.conditions.empty());
  EXPECT_EQ(r.reference.before_reward.size(), 3u);
  EXPECT_EQ(r.heldout_pairs > 0, true);
  EXPECT_GT(r.expert_heldout.success_rate, 0.5);
  // The appendix curve: one point per checkpoint, the expert's level on the same scenarios.
  ASSERT_TRUE(r.curve.has_value());
  ASSERT_EQ(r.curve->points.size(), 3u);
  EXPECT_EQ(r.curve->points[2].epochs, 3);
  EXPECT_GT(r.curve->drill_pairs, 0);
  EXPECT_LE(r.curve->expert.mean_reward, 0.0);
}

TEST(StudentExperiment, StudyCornerEvaluatesOnlyOnTheCornerGoals) {
  StudentExperimentConfig c = tiny_config(2);
  c.region = GoalRegion::StudyCorner;
  c.learning_curve = false;
  c.students.resize(1);
  const StudentExperimentResult r = run_student_experiment(small_kit(), c);
  EXPECT_FALSE(r.curve.has_value());
  EXPECT_EQ(student_experiment_json(r, small_kit()).at("config").at("region"), "study-corner");
  ASSERT_EQ(r.students.size(), 1u);
  EXPECT_EQ(r.students[0].conditions[0].reward.size(), 3u);
}

TEST(StudentExperiment, RehearsalAddsTheStudentsOwnPairsEquallyToEveryCondition) {
  StudentExperimentConfig c = tiny_config(1);
  c.finetune_rehearsal = 1.5;
  const StudentExperimentResult with = run_student_experiment(small_kit(), c);
  const StudentExperimentResult without = run_student_experiment(small_kit(), tiny_config(1));
  for (std::size_t s = 0; s < with.students.size(); ++s)
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t cond = 0; cond < 3; ++cond) {
        const ConditionResult& r = with.students[s].conditions[cond];
        EXPECT_EQ(r.pairs[k], without.students[s].conditions[cond].pairs[k])
            << "the condition's own material is unchanged";
        EXPECT_EQ(r.rehearsal_pairs[k], std::lround(1.5 * r.pairs[k]));
        EXPECT_EQ(without.students[s].conditions[cond].rehearsal_pairs[k], 0);
      }
  EXPECT_NE(with.students[1].conditions[0].reward, without.students[1].conditions[0].reward);
  c.finetune_rehearsal = -1;
  EXPECT_THROW(run_student_experiment(small_kit(), c), InputError);
}

TEST(StudentExperiment, SameSeedSameNumbersOtherSeedOtherNumbers) {
  const Json a = student_experiment_json(run_student_experiment(small_kit(), tiny_config(5)), small_kit());
  const Json b = student_experiment_json(run_student_experiment(small_kit(), tiny_config(5)), small_kit());
  EXPECT_EQ(a, b);
  const Json c = student_experiment_json(run_student_experiment(small_kit(), tiny_config(6)), small_kit());
  EXPECT_NE(a.at("students"), c.at("students"));
}

TEST(StudentExperiment, RefusesEmptyConfigurations) {
  StudentExperimentConfig c = tiny_config(0);
  c.evaluation_sets = 0;
  EXPECT_THROW(run_student_experiment(small_kit(), c), InputError);
  c = tiny_config(0);
  c.students.clear();
  EXPECT_THROW(run_student_experiment(small_kit(), c), InputError);
}

}  // namespace
}  // namespace sc
