#pragma once
// What `skillcoach simulate-students` prints and saves: per student and condition the mean ± standard error
// over the evaluation sets, the Wilcoxon signed-rank tests between conditions (paired by set), the weakest
// skills Alg. 2 found, and everything as JSON.
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/sessions/task_kit.hpp"
#include "teaching/students/student_experiment.hpp"
#include "teaching/students/wilcoxon.hpp"

namespace sc {

struct MeanAndError {
  double mean = 0.0;
  double standard_error = 0.0;  // sample standard deviation / sqrt(n); 0 for n < 2
};
MeanAndError mean_and_standard_error(const std::vector<double>& values);

// Per student, in this order: Ind. Drills vs Full Trajectory, Drills vs Full Trajectory, Ind. Drills vs
// Drills (the paper's three claims), on the per-set mean rewards.
struct ConditionComparison {
  int student = 0;  // index into result.students
  StudyCondition a = StudyCondition::IndDrills;
  StudyCondition b = StudyCondition::FullTrajectory;
  double mean_difference = 0.0;  // mean over sets of reward(a) - reward(b) (last-step reward)
  WilcoxonResult test;
  double step_difference = 0.0;  // the same for the mean per-step reward
  WilcoxonResult step_test;
  double success_difference = 0.0;  // mean over sets of success(a) - success(b)
};
std::vector<ConditionComparison> compare_conditions(const StudentExperimentResult& result);

// Plain-text table (monospace), with the skill descriptions of the kit that ran the experiment.
std::string student_experiment_table(const StudentExperimentResult& result, const TaskKit& kit);
Json student_experiment_json(const StudentExperimentResult& result, const TaskKit& kit);

}  // namespace sc
