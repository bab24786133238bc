#pragma once
// The synthetic-student experiment on the writing task (the parking protocol, student_experiment.hpp,
// with pens instead of cars). For each writing student (writing_students.hpp):
//   1. Alg. 1 picks `diagnosis_words` diverse words of the kit's expert pool; the student writes them
//      (rollout_pen); Alg. 2 on the CompILE segmentation of its traces -> its `num_targets` weakest skills;
//   2. for each of `evaluation_sets` (15) sets of `words_per_set` fresh words (none from the pool), the
//      student writes them before fine-tuning, then copies of it are fine-tuned on equal-size data of
//      Ind. Drills, random Drills and Full Trajectory (whole expert words), drawn by finetune_data.hpp from
//      the pool with fresh random material per set, and write them again;
//   3. the score is the kit's overlap reward (score_writing, in [-1, 0]) on the fresh words; conditions
//      are compared with Wilcoxon signed-rank tests over the sets (writing_student_report.hpp).
// Same kit, config and seed -> the same numbers (sc::Rng and seeded torch throughout, one thread).
#include <cstdint>
#include <string>
#include <vector>

#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/students/student_experiment.hpp"
#include "teaching/students/writing_students.hpp"
#include "teaching/tasks/writing_kit.hpp"

namespace sc {

struct WritingStudentExperimentConfig {
  std::uint64_t seed = 0;
  std::vector<WritingStudentRecipe> students;
  int diagnosis_words = 6;
  int num_targets = 3;
  int finetune_epochs = 10;
  double finetune_learning_rate = 5e-4;  // the paper's BC learning rate
  int finetune_pairs = 0;                // per condition; 0 = one round of Ind. Drills of each set
  double finetune_rehearsal = 0.0;       // as StudentExperimentConfig: round(R x pairs) of the student's own pairs
  int evaluation_sets = 15;
  int words_per_set = 2;

  static WritingStudentExperimentConfig standard();  // the values above, the default students
  // Seconds, for tests and --quick: two tiny students, 2 diagnosis words, 3 sets of 1 word. Concludes nothing.
  static WritingStudentExperimentConfig quick();
  void validate() const;  // InputError for out-of-range values
};

struct WritingConditionResult {
  StudyCondition condition = StudyCondition::IndDrills;
  std::vector<double> reward;         // per evaluation set: mean overlap reward
  std::vector<int> pairs;             // per set: fine-tuning pairs (equal across conditions)
  std::vector<int> letter_pairs;      // per set: of which in the student's letter (true character bounds)
  std::vector<double> finetune_loss;  // per set: last epoch's training MSE
  std::vector<int> rehearsal_pairs;   // per set
};

struct WritingStudentResult {
  WritingStudentRecipe recipe;
  int training_pairs = 0;
  int letter_pairs = 0;  // expert pairs of its letter (left out or mirrored)
  double training_loss = 0.0;
  double expert_mse = 0.0;
  double diagnosis_reward = 0.0;  // mean reward of its diagnosis traces
  ExpertiseEstimate diagnosis;
  std::vector<double> before_reward;               // per evaluation set
  std::vector<WritingConditionResult> conditions;  // kFinetuneConditions order
  const WritingConditionResult& of(StudyCondition condition) const;
};

struct WritingStudentExperimentResult {
  WritingStudentExperimentConfig config;
  std::string extractor;
  std::string extractor_notice;
  int pool_size = 0;
  int expert_pairs = 0;
  std::vector<int> diagnosis_words;                        // pool indices picked by Alg. 1
  std::vector<std::vector<std::string>> evaluation_words;  // per set
  std::vector<WritingStudentResult> students;
};

// kit: the classic-alphabet writing kit (InputError for another alphabet).
WritingStudentExperimentResult run_writing_student_experiment(const WritingKit& kit,
                                                              const WritingStudentExperimentConfig& config,
                                                              const ExperimentProgress& progress = {});

}  // namespace sc
