#include "teaching/students/student_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/core/task_kind.hpp"
#include "engine/parking/parking_trial.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/students/bc_datasets.hpp"
#include "teaching/students/experiment_seeds.hpp"
#include "teaching/students/finetune_data.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

using namespace experiment_seeds;  // NOLINT: the streams and derived_seed, shared with the other task

void report(const ExperimentProgress& progress, const std::string& phase, int done, int total) {
  if (progress) progress(phase, done, total);
}

// `count` fresh scenarios of the region, none equal to a pool scenario (`taken`: the pool's, parsed once).
std::vector<ParkingScenario> evaluation_set(std::vector<ParkingScenario> taken, const StudentExperimentConfig& config,
                                            int set) {
  std::vector<ParkingScenario> out;
  const std::uint64_t seed = derived_seed(config.seed, kEvaluationSet, static_cast<std::uint64_t>(set));
  for (int i = 0; static_cast<int>(out.size()) < config.scenarios_per_set; ++i) {
    const ParkingScenario s = parking_pool_scenario(seed, i, config.region);
    if (std::find(taken.begin(), taken.end(), s) != taken.end()) continue;
    taken.push_back(s);
    out.push_back(s);
  }
  return out;
}

// Alg. 2 on the student's own rollouts of the diagnosis scenarios.
void diagnose(const TaskKit& kit, const std::vector<int>& picks, const StudentExperimentConfig& config,
              const BcPolicy& policy, StudentResult& out, const ExperimentProgress& progress,
              const std::string& phase) {
  std::vector<ExpertiseTrial> trials;
  for (std::size_t k = 0; k < picks.size(); ++k) {
    const ExpertDemo& demo = kit.expert_pool()[static_cast<std::size_t>(picks[k])];
    const ParkingTrial t = rollout_parking_student(policy, parse_parking_scenario(JsonView(demo.scenario, "pool")));
    const double score = parking_episode_score(t);
    out.diagnosis_reward += score / static_cast<double>(picks.size());
    out.diagnosis_success += (t.success.value_or(false) ? 1.0 : 0.0) / static_cast<double>(picks.size());
    trials.push_back({picks[k], demo.skills, kit.extractor().extract(parking_step_sequence(t)), score});
    report(progress, phase, static_cast<int>(k) + 1, static_cast<int>(picks.size()));
  }
  out.diagnosis = estimate_expertise(trials, kit.extractor().num_skills(), config.num_targets);
}

// The drives students learn from and are measured on: planned here, apart from the kit's pool.
struct StudentDrives {
  BcDataset training;
  std::vector<ParkingScenario> heldout_scenarios;
  BcDataset heldout;
};

StudentDrives plan_student_drives(const StudentExperimentConfig& config, StudentExperimentResult& result,
                                  const ExperimentProgress& progress) {
  StudentDrives d;
  const int total = config.student_drives + config.heldout_drives;
  const std::string phase = "planning expert drives";
  d.training = bc_dataset_from_trials(
      plan_expert_drives(config.student_drives, derived_seed(config.seed, kStudentDrives), GoalRegion::WholeLot,
                         [&](int done) { report(progress, phase, done, total); }));
  const std::vector<ParkingTrial> heldout =
      plan_expert_drives(config.heldout_drives, derived_seed(config.seed, kHeldoutDrives), GoalRegion::WholeLot,
                         [&](int done) { report(progress, phase, config.student_drives + done, total); });
  d.heldout = bc_dataset_from_trials(heldout);
  for (const ParkingTrial& t : heldout) {
    d.heldout_scenarios.push_back(t.scenario);
    const double n = static_cast<double>(heldout.size());
    result.expert_heldout.mean_reward += parking_episode_score(t) / n;
    result.expert_heldout.step_reward += parking_mean_step_reward(t) / n;
    result.expert_heldout.success_rate += (t.success.value_or(false) ? 1.0 : 0.0) / n;
  }
  result.student_pairs = d.training.size();
  result.heldout_pairs = d.heldout.size();
  return d;
}

SyntheticStudent train_and_measure(const SyntheticStudentRecipe& recipe, const StudentDrives& drives,
                                   std::uint64_t seed, StudentResult& r) {
  SyntheticStudent student = train_synthetic_student(recipe, drives.training, seed);
  r.recipe = recipe;
  r.training_pairs = student.training_pairs;
  r.reverse_pairs_total = student.reverse_pairs_total;
  r.reverse_pairs_kept = student.reverse_pairs_kept;
  r.training_loss = student.training_loss;
  r.expert_mse = student.expert_mse;
  r.heldout_mse = split_mse(student.policy, drives.heldout);
  r.heldout = score_parking_student(student.policy, drives.heldout_scenarios);
  return student;
}

// One evaluation set: the student as it is, then a fine-tuned copy per condition on equal-size data.
void run_evaluation_set(const SyntheticStudent& student, const FinetuneMaterial& material,
                        const StudentExperimentConfig& config, std::size_t s, int k,
                        const std::vector<ParkingScenario>& set, const BcDataset& heldout, StudentResult& r,
                        const std::function<void()>& tick) {
  const ParkingScore before = score_parking_student(student.policy, set);
  r.before_reward.push_back(before.mean_reward);
  r.before_step_reward.push_back(before.step_reward);
  r.before_success.push_back(before.success_rate);
  tick();
  const std::uint64_t data_seed = derived_seed(config.seed, kFinetuneData, static_cast<std::uint64_t>(k));
  const int pairs = config.finetune_pairs > 0 ? config.finetune_pairs : individualized_round_pairs(material, data_seed);
  const int own = static_cast<int>(std::lround(config.finetune_rehearsal * pairs));
  const BcDataset rehearsal = sample_pairs(student.training_data, own, derived_seed(config.seed, kRehearsal, s, k));
  for (ConditionResult& out : r.conditions) {
    const FinetuneData data = finetune_data(out.condition, material, pairs, data_seed);
    BcDataset training_pairs = data.pairs;
    if (own > 0) training_pairs.append(rehearsal);
    BcPolicy copy = student.policy.clone();
    BcTrainingConfig training;
    training.epochs = config.finetune_epochs;
    training.learning_rate = config.finetune_learning_rate;
    training.seed = derived_seed(config.seed, kFinetuneTraining, s, k);  // same for every condition: paired
    out.finetune_loss.push_back(copy.train(training_pairs, training));
    const ParkingScore after = score_parking_student(copy, set);
    out.reward.push_back(after.mean_reward);
    out.step_reward.push_back(after.step_reward);
    out.success.push_back(after.success_rate);
    out.pairs.push_back(data.pairs.size());
    out.reverse_pairs.push_back(count_reverse_pairs(data.pairs));
    out.rehearsal_pairs.push_back(rehearsal.size());
    out.heldout_mse.push_back(split_mse(copy, heldout));
    tick();
  }
}

LearningCurve learning_curve(const SyntheticStudent& student, const FinetuneMaterial& material,
                             const StudentExperimentConfig& config, const ExperimentProgress& progress) {
  report(progress, "learning curve", 0, 1);
  LearningCurveConfig curve = config.curve;
  curve.learning_rate = config.finetune_learning_rate;
  curve.rehearsal = config.finetune_rehearsal;
  curve.seed = derived_seed(config.seed, kCurve);
  std::vector<ParkingScenario> scenarios;
  for (int i = 0; i < curve.rollouts; ++i)
    scenarios.push_back(parking_pool_scenario(derived_seed(curve.seed, kEvaluationSet), i, config.region));
  LearningCurve out = fixed_drill_learning_curve(student.policy, student.training_data, material, scenarios, curve);
  report(progress, "learning curve", 1, 1);
  return out;
}

}  // namespace

StudentExperimentConfig StudentExperimentConfig::paper() {
  StudentExperimentConfig c;
  for (SyntheticStudentKind kind : {SyntheticStudentKind::HalfTrained, SyntheticStudentKind::ReversingDifficulty})
    c.students.push_back(SyntheticStudentRecipe::paper(kind));
  return c;
}

StudentExperimentConfig StudentExperimentConfig::quick() {
  StudentExperimentConfig c = paper();
  c.students[0].epochs = 5;
  c.students[1].epochs = 20;
  c.reference.epochs = 20;
  c.student_drives = 40;
  c.heldout_drives = 10;
  c.diagnosis_scenarios = 8;
  c.finetune_epochs = 20;
  c.evaluation_sets = 4;
  c.scenarios_per_set = 4;
  c.curve.checkpoints = {0, 5, 20};
  c.curve.rollouts = 8;
  return c;
}

void StudentExperimentConfig::validate() const {
  auto positive = [](int v, const char* name) {
    if (v < 1) throw InputError("synthetic students", std::string(name) + " must be >= 1, got " + std::to_string(v));
  };
  positive(static_cast<int>(students.size()), "the number of students");
  positive(student_drives, "student_drives");
  positive(heldout_drives, "heldout_drives");
  positive(diagnosis_scenarios, "diagnosis_scenarios");
  positive(num_targets, "num_targets");
  positive(finetune_epochs, "finetune_epochs");
  positive(evaluation_sets, "evaluation_sets");
  positive(scenarios_per_set, "scenarios_per_set");
  if (finetune_pairs < 0)
    throw InputError("synthetic students", "finetune_pairs must be >= 0 (0 = one Ind. Drills round)");
  if (!(finetune_rehearsal >= 0.0 && finetune_rehearsal <= 100.0))
    throw InputError("synthetic students",
                     "finetune_rehearsal must lie in [0, 100], got " + std::to_string(finetune_rehearsal));
  if (!(finetune_learning_rate > 0.0 && finetune_learning_rate <= 1.0))
    throw InputError("synthetic students",
                     "finetune_learning_rate must lie in (0, 1], got " + std::to_string(finetune_learning_rate));
  for (const SyntheticStudentRecipe& r : students) positive(r.epochs, "student epochs");
  positive(reference.epochs, "reference student epochs");
  if (learning_curve) curve.validate();
}

const ConditionResult& StudentResult::of(StudyCondition condition) const {
  for (const ConditionResult& c : conditions)
    if (c.condition == condition) return c;
  throw InputError("synthetic students", std::string(condition_name(condition)) + " was not run");
}

StudentExperimentResult run_student_experiment(const TaskKit& kit, const StudentExperimentConfig& config,
                                               const ExperimentProgress& progress) {
  config.validate();
  if (task_kind_of(kit.task()) != TaskKind::parking)
    throw InputError("synthetic students", "the experiment needs the parking kit");
  configure_torch_threads();
  StudentExperimentResult result;
  result.config = config;
  result.extractor = kit.extractor().name();
  result.extractor_notice = kit.extractor_notice();
  const std::vector<ExpertDemo>& pool = kit.expert_pool();
  result.pool_size = static_cast<int>(pool.size());
  for (const ExpertDemo& d : pool) result.expert_pool_reward += d.reward / static_cast<double>(pool.size());
  result.expert_pairs = bc_dataset_from_steps(demo_steps(pool)).size();
  result.diagnosis_scenarios = select_diverse_scenarios(demo_skills(pool), config.diagnosis_scenarios).scenarios();
  const StudentDrives drives = plan_student_drives(config, result, progress);
  std::vector<std::vector<ParkingScenario>> sets;
  std::vector<ParkingScenario> pool_scenarios;
  for (std::size_t i = 0; i < pool.size(); ++i)
    pool_scenarios.push_back(parse_parking_scenario(JsonView(pool[i].scenario, "pool scenario " + std::to_string(i))));
  for (int k = 0; k < config.evaluation_sets; ++k) sets.push_back(evaluation_set(pool_scenarios, config, k));

  report(progress, "training fully trained", 0, 1);
  const std::size_t reference_stream = config.students.size();
  const SyntheticStudent reference = train_and_measure(
      config.reference, drives, derived_seed(config.seed, kStudentInit, reference_stream), result.reference);
  report(progress, "training fully trained", 1, 1);
  diagnose(kit, result.diagnosis_scenarios, config, reference.policy, result.reference, progress,
           "diagnosing fully trained");
  for (const std::vector<ParkingScenario>& set : sets) {
    const ParkingScore before = score_parking_student(reference.policy, set);
    result.reference.before_reward.push_back(before.mean_reward);
    result.reference.before_step_reward.push_back(before.step_reward);
    result.reference.before_success.push_back(before.success_rate);
  }

  for (std::size_t s = 0; s < config.students.size(); ++s) {
    const std::string name(student_name(config.students[s].kind));
    report(progress, "training " + name, 0, 1);
    StudentResult r;
    const SyntheticStudent student =
        train_and_measure(config.students[s], drives, derived_seed(config.seed, kStudentInit, s), r);
    report(progress, "training " + name, 1, 1);
    diagnose(kit, result.diagnosis_scenarios, config, student.policy, r, progress, "diagnosing " + name);
    const FinetuneMaterial material{demo_steps(pool), demo_skills(pool), r.diagnosis, config.num_targets};
    for (StudyCondition c : kFinetuneConditions)
      r.conditions.push_back(ConditionResult{c, {}, {}, {}, {}, {}, {}, {}, {}});
    if (config.learning_curve && r.recipe.kind == SyntheticStudentKind::ReversingDifficulty)
      result.curve = learning_curve(student, material, config, progress);
    const int units = config.evaluation_sets * (1 + static_cast<int>(r.conditions.size()));
    int done = 0;
    for (int k = 0; k < config.evaluation_sets; ++k)
      run_evaluation_set(student, material, config, s, k, sets[static_cast<std::size_t>(k)], drives.heldout, r,
                         [&] { report(progress, "fine-tuning " + name, ++done, units); });
    result.students.push_back(std::move(r));
  }
  return result;
}

}  // namespace sc
