#include "teaching/students/learning_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "teaching/students/bc_datasets.hpp"

namespace sc {
namespace {

ParkingScore expert_score(const std::vector<ParkingScenario>& scenarios) {
  const ParkingExpert expert;
  ParkingScore out;
  const double n = static_cast<double>(scenarios.size());
  for (const ParkingScenario& s : scenarios) {
    const ParkingTrial t = expert.plan(s).to_trial(s);
    out.mean_reward += parking_episode_score(t) / n;
    out.step_reward += parking_mean_step_reward(t) / n;
    out.success_rate += (t.success.value_or(false) ? 1.0 : 0.0) / n;
  }
  return out;
}

}  // namespace

void LearningCurveConfig::validate() const {
  if (checkpoints.empty()) throw InputError("learning curve", "needs at least one checkpoint");
  for (std::size_t i = 0; i < checkpoints.size(); ++i) {
    if (checkpoints[i] < 0) throw InputError("learning curve", "checkpoint epochs must be >= 0");
    if (i > 0 && checkpoints[i] <= checkpoints[i - 1]) throw InputError("learning curve", "checkpoints must ascend");
  }
  if (rollouts < 1) throw InputError("learning curve", "rollouts must be >= 1, got " + std::to_string(rollouts));
}

LearningCurve fixed_drill_learning_curve(const BcPolicy& student, const BcDataset& own_pairs,
                                         const FinetuneMaterial& material,
                                         const std::vector<ParkingScenario>& scenarios,
                                         const LearningCurveConfig& config) {
  config.validate();
  if (static_cast<int>(scenarios.size()) < config.rollouts)
    throw InputError("learning curve", "needs " + std::to_string(config.rollouts) + " scenarios, got " +
                                           std::to_string(scenarios.size()));
  const std::vector<ParkingScenario> rollouts(scenarios.begin(), scenarios.begin() + config.rollouts);
  const std::uint64_t data_seed = Rng(config.seed).fork(1).next_u64();
  const int pairs = individualized_round_pairs(material, data_seed);
  BcDataset data = finetune_data(StudyCondition::IndDrills, material, pairs, data_seed).pairs;
  LearningCurve curve;
  curve.drill_pairs = data.size();
  curve.reverse_pairs = count_reverse_pairs(data);
  const int own = static_cast<int>(std::lround(config.rehearsal * pairs));
  const BcDataset rehearsal = sample_pairs(own_pairs, own, Rng(config.seed).fork(2).next_u64());
  curve.rehearsal_pairs = rehearsal.size();
  data.append(rehearsal);
  curve.expert = expert_score(rollouts);

  BcPolicy copy = student.clone();
  std::size_t next = 0;
  if (config.checkpoints.front() == 0) {
    curve.points.push_back({0, score_parking_student(copy, rollouts), 0.0});
    ++next;
  }
  if (next == config.checkpoints.size()) return curve;
  BcTrainingConfig training;
  training.epochs = config.checkpoints.back();
  training.learning_rate = config.learning_rate;
  training.seed = Rng(config.seed).fork(3).next_u64();
  training.after_epoch = [&](int epoch, double loss) {
    if (next < config.checkpoints.size() && epoch == config.checkpoints[next]) {
      curve.points.push_back({epoch, score_parking_student(copy, rollouts), loss});
      ++next;
    }
  };
  copy.train(data, training);
  return curve;
}

}  // namespace sc
