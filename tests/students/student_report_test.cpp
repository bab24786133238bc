#include "teaching/students/student_report.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace sc {
namespace {

TEST(StudentReport, MeanAndStandardErrorOverSets) {
  const MeanAndError m = mean_and_standard_error({1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_NEAR(m.standard_error, std::sqrt(5.0 / 3.0) / 2.0, 1e-12);  // sd = sqrt(5/3), n = 4
  EXPECT_DOUBLE_EQ(mean_and_standard_error({7}).standard_error, 0.0);
  EXPECT_DOUBLE_EQ(mean_and_standard_error({}).mean, 0.0);
}

TEST(StudentReport, ComparesConditionsPairedBySet) {
  StudentExperimentResult r;
  StudentResult s;
  s.recipe = SyntheticStudentRecipe::paper(SyntheticStudentKind::ReversingDifficulty);
  // Ind. Drills beats Full Trajectory on all six sets; Drills ties with it on average.
  // The per-step rewards are half the last-step ones; success is 1 for Ind. Drills, 0.5 otherwise.
  const std::vector<double> ind{-0.1, -0.2, -0.1, -0.3, -0.2, -0.1}, drills{-0.5, -0.3, -0.4, -0.3, -0.6, -0.3},
      full{-0.4, -0.4, -0.5, -0.4, -0.5, -0.2};
  auto half = [](std::vector<double> v) {
    for (double& x : v) x /= 2;
    return v;
  };
  const std::vector<double> all(6, 1.0), some(6, 0.5);
  s.conditions = {{StudyCondition::IndDrills, ind, half(ind), all, {}, {}, {}, {}, {}},
                  {StudyCondition::Drills, drills, half(drills), some, {}, {}, {}, {}, {}},
                  {StudyCondition::FullTrajectory, full, half(full), some, {}, {}, {}, {}, {}}};
  r.students = {s};
  const std::vector<ConditionComparison> c = compare_conditions(r);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].a, StudyCondition::IndDrills);
  EXPECT_EQ(c[0].b, StudyCondition::FullTrajectory);
  EXPECT_NEAR(c[0].mean_difference, 1.4 / 6.0, 1e-12);  // differences 0.3, 0.2, 0.4, 0.1, 0.3, 0.1
  EXPECT_EQ(c[0].test.w_minus, 0.0);
  EXPECT_LT(c[0].test.p_two_sided, 0.05);
  EXPECT_NEAR(c[0].step_difference, 0.7 / 6.0, 1e-12);
  EXPECT_EQ(c[0].step_test.p_two_sided, c[0].test.p_two_sided);
  EXPECT_NEAR(c[0].success_difference, 0.5, 1e-12);
  EXPECT_EQ(c[1].a, StudyCondition::Drills);
  EXPECT_NEAR(c[1].mean_difference, 0.0, 1e-12);
  EXPECT_GT(c[1].test.p_two_sided, 0.5);
  EXPECT_EQ(c[2].b, StudyCondition::Drills);
}

}  // namespace
}  // namespace sc
