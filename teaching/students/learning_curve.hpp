#pragma once
// The paper's appendix figure "Impact of Training Time on Synthetic Student": the reversing-difficulty
// student fine-tuned on a FIXED set of 3 drills (one round of Ind. Drills: one drill for each of its three
// weakest skills) for a growing number of epochs, its mean reward over 100 fresh rollouts at each
// checkpoint, and the expert planner's mean reward on the same scenarios as the level to approach.
// One training run: the checkpoints are read off it after their epoch (BcTrainingConfig::after_epoch), so
// the Adam state carries on as in a single long fine-tuning.
#include <cstdint>
#include <vector>

#include "engine/parking/parking_scenario.hpp"
#include "teaching/students/finetune_data.hpp"
#include "teaching/students/parking_student_rollout.hpp"

namespace sc {

struct LearningCurveConfig {
  std::vector<int> checkpoints = {0, 5, 10, 25, 50, 100, 200, 300, 400};  // epochs, ascending
  int rollouts = 100;  // fresh scenarios scored at each checkpoint (paper: 100 rollouts)
  double learning_rate = 5e-4;
  double rehearsal = 0.0;  // as StudentExperimentConfig::finetune_rehearsal
  std::uint64_t seed = 0;
  void validate() const;  // InputError: empty or unsorted checkpoints, negative epochs, rollouts < 1
};

struct LearningCurvePoint {
  int epochs = 0;
  ParkingScore score;  // over the rollouts' scenarios
  double loss = 0.0;   // that epoch's training MSE (0 at epoch 0)
};

struct LearningCurve {
  int drill_pairs = 0;      // the fixed drill set's pairs
  int reverse_pairs = 0;    // of which u0 < 0
  int rehearsal_pairs = 0;  // the student's own pairs added (rehearsal)
  ParkingScore expert;      // the expert planner on the same scenarios
  std::vector<LearningCurvePoint> points;
};

// student: the policy to fine-tune (copied, not changed); own_pairs: its training pairs (rehearsal);
// scenarios: the rollouts' scenarios (config.rollouts of them are used).
LearningCurve fixed_drill_learning_curve(const BcPolicy& student, const BcDataset& own_pairs,
                                         const FinetuneMaterial& material,
                                         const std::vector<ParkingScenario>& scenarios,
                                         const LearningCurveConfig& config);

}  // namespace sc
