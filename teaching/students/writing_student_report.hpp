#pragma once
// What `skillcoach simulate-students --task writing` prints and saves: per writing student and condition
// the mean ± s.e. of the overlap reward over the evaluation sets, the Wilcoxon signed-rank tests between
// conditions (paired by set), the weakest skills Alg. 2 found, and everything as JSON.
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/students/student_report.hpp"
#include "teaching/students/writing_student_experiment.hpp"

namespace sc {

// Per student: Ind. Drills vs Full Trajectory, Drills vs Full Trajectory, Ind. Drills vs Drills (per-set
// mean rewards), then Ind. Drills vs before (did fine-tuning help at all).
struct WritingComparison {
  int student = 0;
  std::string a;  // condition names ("before" for the untouched student)
  std::string b;
  double mean_difference = 0.0;  // mean over sets of reward(a) - reward(b)
  WilcoxonResult test;
};
std::vector<WritingComparison> compare_writing_conditions(const WritingStudentExperimentResult& result);

std::string writing_experiment_table(const WritingStudentExperimentResult& result, const WritingKit& kit);
Json writing_experiment_json(const WritingStudentExperimentResult& result, const WritingKit& kit);

}  // namespace sc
