#pragma once
// The synthetic-student experiment of the paper (§5 "Does individualization help synthetic students?",
// appendix): the students (and a fully trained yardstick) are cloned on `student_drives` expert drives kept
// apart from the kit's teaching pool and measured on `heldout_drives` others (expert_drives.hpp); then for
// each synthetic parking student
//   1. Alg. 1 picks `diagnosis_scenarios` (25) diverse scenarios from the kit's expert pool;
//   2. the student drives them in ParkingSim; Alg. 2 on those rollouts -> its `num_targets` (3) weakest skills;
//   3. for each of `evaluation_sets` (15) sets of fresh scenarios (none from the pool; goals in `region`,
//      the pool's region for the study corner), copies of the student
//      are fine-tuned `finetune_epochs` (100) epochs on equal-size data of Ind. Drills, random Drills and
//      Full Trajectory (finetune_data.hpp; fresh random material per set) and evaluated on the set;
//   4. conditions are compared with Wilcoxon signed-rank tests over the sets (student_report.hpp).
// Same kit, config and seed -> the same numbers (sc::Rng and seeded torch throughout, one thread).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/parking/parking_scenario.hpp"
#include "teaching/curricula/study_condition.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/sessions/task_kit.hpp"
#include "teaching/students/expert_drives.hpp"
#include "teaching/students/learning_curve.hpp"
#include "teaching/students/parking_student_rollout.hpp"
#include "teaching/students/synthetic_students.hpp"

namespace sc {

inline constexpr StudyCondition kFinetuneConditions[] = {StudyCondition::IndDrills, StudyCondition::Drills,
                                                         StudyCondition::FullTrajectory};

struct StudentExperimentConfig {
  std::uint64_t seed = 0;
  std::vector<SyntheticStudentRecipe> students;  // fine-tuned
  SyntheticStudentRecipe reference = SyntheticStudentRecipe::paper(SyntheticStudentKind::FullyTrained);
  int student_drives = 600;                  // expert drives (whole lot) the students are cloned on, none in the pool
  int heldout_drives = 200;                  // expert drives no student saw: held-out MSE and success
  GoalRegion region = GoalRegion::WholeLot;  // goals of the evaluation sets (the kit's pool should match)
  int diagnosis_scenarios = 25;
  int num_targets = 3;
  int finetune_epochs = 100;
  double finetune_learning_rate = 5e-4;  // the students' own (paper appendix)
  int finetune_pairs = 0;                // per condition; 0 = one round of Ind. Drills of each set (finetune_data.hpp)
  // Ours, not the paper's: every condition's fine-tuning data also holds round(rehearsal x pairs) of the
  // student's own training pairs (the same draw for every condition of a set), the usual remedy for
  // forgetting what the practice material does not show. 0 = the paper's protocol.
  double finetune_rehearsal = 0.0;
  int evaluation_sets = 15;
  int scenarios_per_set = 20;
  // The appendix curve for the reversing-difficulty student (when it is among `students`); its
  // learning_rate, rehearsal and seed are taken from this config. Off: no checkpoints.
  bool learning_curve = true;
  LearningCurveConfig curve;

  static StudentExperimentConfig paper();  // the values above, both paper students
  // Seconds instead of minutes, for tests and --quick: 20/80-epoch students, 8 diagnosis scenarios,
  // 20 fine-tuning epochs, 4 sets of 4 scenarios. Same protocol, far too small to conclude anything.
  static StudentExperimentConfig quick();
  void validate() const;  // InputError for non-positive counts
};

struct ConditionResult {
  StudyCondition condition = StudyCondition::IndDrills;
  std::vector<double> reward;         // per evaluation set: mean episode score (last-step reward)
  std::vector<double> step_reward;    // per evaluation set: mean per-step reward
  std::vector<double> success;        // per evaluation set: success rate
  std::vector<int> pairs;             // per set: fine-tuning pairs (equal across conditions)
  std::vector<int> reverse_pairs;     // per set: of which with reverse acceleration (u0 < 0)
  std::vector<double> finetune_loss;  // per set: last epoch's training MSE
  std::vector<int> rehearsal_pairs;   // per set: the student's own pairs added (finetune_rehearsal)
  // Per set: the fine-tuned copy's action error on the held-out drives, split by the expert's acceleration
  // sign: whether practice fixed the actions it was meant to (reversing) and what it cost elsewhere.
  std::vector<SplitMse> heldout_mse;
};

struct StudentResult {
  SyntheticStudentRecipe recipe;
  int training_pairs = 0;
  int reverse_pairs_total = 0;
  int reverse_pairs_kept = 0;
  double training_loss = 0.0;
  double expert_mse = 0.0;        // on its training drives' pairs (all of them, dropped reverse ones too)
  SplitMse heldout_mse;           // on the held-out drives' pairs
  ParkingScore heldout;           // driving the held-out drives' scenarios itself
  double diagnosis_reward = 0.0;  // mean score of its rollouts on the diagnosis scenarios
  double diagnosis_success = 0.0;
  ExpertiseEstimate diagnosis;        // Alg. 2; targets = its weakest skills
  std::vector<double> before_reward;  // per evaluation set, without fine-tuning
  std::vector<double> before_step_reward;
  std::vector<double> before_success;
  std::vector<ConditionResult> conditions;  // in kFinetuneConditions order
  const ConditionResult& of(StudyCondition condition) const;
};

struct StudentExperimentResult {
  StudentExperimentConfig config;
  std::string extractor;         // "compile" or "time-heuristic"
  std::string extractor_notice;  // why a fallback is used ("" for the trained model)
  int pool_size = 0;
  int expert_pairs = 0;   // the pool's
  int student_pairs = 0;  // the student drives' (before any filter)
  int heldout_pairs = 0;
  ParkingScore expert_heldout;           // the expert planner on the held-out drives' scenarios
  StudentResult reference;               // the fully trained student: measured, diagnosed, not fine-tuned
  double expert_pool_reward = 0.0;       // the expert's mean episode score on its pool
  std::vector<int> diagnosis_scenarios;  // pool indices picked by Alg. 1
  std::vector<StudentResult> students;
  std::optional<LearningCurve> curve;  // the reversing-difficulty student's (config.learning_curve)
};

// phase: what runs ("training half-trained", ...); done of total units of that phase.
using ExperimentProgress = std::function<void(std::string_view phase, int done, int total)>;

// kit: a parking kit (InputError otherwise); its pool supplies the diagnosis scenarios and every drill.
StudentExperimentResult run_student_experiment(const TaskKit& kit, const StudentExperimentConfig& config,
                                               const ExperimentProgress& progress = {});

}  // namespace sc
