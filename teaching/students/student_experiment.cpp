#include "teaching/students/student_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_trial.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/students/bc_datasets.hpp"
#include "teaching/students/finetune_data.hpp"
#include "teaching/students/parking_student_rollout.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

// Independent, reorder-stable seeds for each use (streams of Rng::fork).
enum SeedStream : std::uint64_t { kStudentInit = 1, kEvaluationSet = 2, kFinetuneData = 3, kFinetuneTraining = 4,
                             kRehearsal = 5 };

std::uint64_t derived_seed(std::uint64_t seed, SeedStream stream, std::uint64_t a = 0, std::uint64_t b = 0) {
  return Rng(seed).fork(stream).fork(a).fork(b).next_u64();
}

void report(const ExperimentProgress& progress, const std::string& phase, int done, int total) {
  if (progress) progress(phase, done, total);
}

std::vector<ParkingScenario> parse_scenarios(const std::vector<Json>& docs, const std::string& what) {
  std::vector<ParkingScenario> out;
  for (std::size_t i = 0; i < docs.size(); ++i)
    out.push_back(parse_parking_scenario(JsonView(docs[i], what + " " + std::to_string(i))));
  return out;
}

// Alg. 2 on the student's own rollouts of the diagnosis scenarios.
void diagnose(const TaskKit& kit, const std::vector<int>& picks, const StudentExperimentConfig& config,
              const BcPolicy& policy, StudentResult& out, const ExperimentProgress& progress, const std::string& phase) {
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

}  // namespace

StudentExperimentConfig StudentExperimentConfig::paper() {
  StudentExperimentConfig c;
  for (SyntheticStudentKind kind : kSyntheticStudentKinds) c.students.push_back(SyntheticStudentRecipe::paper(kind));
  return c;
}

StudentExperimentConfig StudentExperimentConfig::quick() {
  StudentExperimentConfig c = paper();
  c.students[0].epochs = 20;
  c.students[1].epochs = 80;
  c.diagnosis_scenarios = 8;
  c.finetune_epochs = 20;
  c.evaluation_sets = 4;
  c.scenarios_per_set = 4;
  return c;
}

void StudentExperimentConfig::validate() const {
  auto positive = [](int v, const char* name) {
    if (v < 1) throw InputError("synthetic students", std::string(name) + " must be >= 1, got " + std::to_string(v));
  };
  positive(static_cast<int>(students.size()), "the number of students");
  positive(diagnosis_scenarios, "diagnosis_scenarios");
  positive(num_targets, "num_targets");
  positive(finetune_epochs, "finetune_epochs");
  positive(evaluation_sets, "evaluation_sets");
  positive(scenarios_per_set, "scenarios_per_set");
  if (finetune_pairs < 0) throw InputError("synthetic students", "finetune_pairs must be >= 0 (0 = one Ind. Drills round)");
  if (!(finetune_rehearsal >= 0.0 && finetune_rehearsal <= 100.0))
    throw InputError("synthetic students", "finetune_rehearsal must lie in [0, 100], got " + std::to_string(finetune_rehearsal));
  for (const SyntheticStudentRecipe& r : students) positive(r.epochs, "student epochs");
}

const ConditionResult& StudentResult::of(StudyCondition condition) const {
  for (const ConditionResult& c : conditions)
    if (c.condition == condition) return c;
  throw InputError("synthetic students", std::string(condition_name(condition)) + " was not run");
}

StudentExperimentResult run_student_experiment(const TaskKit& kit, const StudentExperimentConfig& config,
                                               const ExperimentProgress& progress) {
  config.validate();
  if (kit.task() != "parking") throw InputError("synthetic students", "the experiment needs the parking kit");
  configure_torch_threads();
  StudentExperimentResult result;
  result.config = config;
  result.extractor = kit.extractor().name();
  result.extractor_notice = kit.extractor_notice();
  const std::vector<ExpertDemo>& pool = kit.expert_pool();
  result.pool_size = static_cast<int>(pool.size());
  for (const ExpertDemo& d : pool) result.expert_pool_reward += d.reward / static_cast<double>(pool.size());
  const BcDataset expert_pairs = bc_dataset_from_steps(demo_steps(pool));
  result.expert_pairs = expert_pairs.size();
  result.diagnosis_scenarios = select_diverse_scenarios(demo_skills(pool), config.diagnosis_scenarios).scenarios();

  std::vector<Json> pool_scenarios;
  for (const ExpertDemo& d : pool) pool_scenarios.push_back(d.scenario);
  std::vector<std::vector<ParkingScenario>> sets;
  for (int k = 0; k < config.evaluation_sets; ++k)
    sets.push_back(parse_scenarios(
        kit.fresh_scenarios(config.scenarios_per_set, derived_seed(config.seed, kEvaluationSet, k), pool_scenarios),
        "evaluation scenario"));

  for (std::size_t s = 0; s < config.students.size(); ++s) {
    const SyntheticStudentRecipe& recipe = config.students[s];
    const std::string name(student_name(recipe.kind));
    report(progress, "training " + name, 0, 1);
    const SyntheticStudent student = train_synthetic_student(recipe, expert_pairs, derived_seed(config.seed, kStudentInit, s));
    report(progress, "training " + name, 1, 1);
    StudentResult r;
    r.recipe = recipe;
    r.training_pairs = student.training_pairs;
    r.reverse_pairs_total = student.reverse_pairs_total;
    r.reverse_pairs_kept = student.reverse_pairs_kept;
    r.training_loss = student.training_loss;
    r.expert_mse = student.expert_mse;
    diagnose(kit, result.diagnosis_scenarios, config, student.policy, r, progress, "diagnosing " + name);

    FinetuneMaterial material{demo_steps(pool), demo_skills(pool), r.diagnosis, config.num_targets};
    for (StudyCondition c : kFinetuneConditions) r.conditions.push_back(ConditionResult{c, {}, {}, {}, {}, {}, {}});
    const int units = config.evaluation_sets * (1 + static_cast<int>(r.conditions.size()));
    const std::string phase = "fine-tuning " + name;
    for (int k = 0; k < config.evaluation_sets; ++k) {
      const ParkingScore before = score_parking_student(student.policy, sets[static_cast<std::size_t>(k)]);
      r.before_reward.push_back(before.mean_reward);
      r.before_success.push_back(before.success_rate);
      report(progress, phase, k * (1 + static_cast<int>(r.conditions.size())) + 1, units);
      const std::uint64_t data_seed = derived_seed(config.seed, kFinetuneData, k);
      const int pairs = config.finetune_pairs > 0 ? config.finetune_pairs : individualized_round_pairs(material, data_seed);
      const int own = static_cast<int>(std::lround(config.finetune_rehearsal * pairs));
      const BcDataset rehearsal = sample_pairs(student.training_data, own, derived_seed(config.seed, kRehearsal, s, k));
      for (std::size_t c = 0; c < r.conditions.size(); ++c) {
        ConditionResult& out = r.conditions[c];
        const FinetuneData data = finetune_data(out.condition, material, pairs, data_seed);
        BcDataset training_pairs = data.pairs;
        if (own > 0) training_pairs.append(rehearsal);
        BcPolicy copy = student.policy.clone();
        BcTrainingConfig training;
        training.epochs = config.finetune_epochs;
        training.seed = derived_seed(config.seed, kFinetuneTraining, s, k);  // same for every condition: paired
        out.finetune_loss.push_back(copy.train(training_pairs, training));
        const ParkingScore after = score_parking_student(copy, sets[static_cast<std::size_t>(k)]);
        out.reward.push_back(after.mean_reward);
        out.success.push_back(after.success_rate);
        out.pairs.push_back(data.pairs.size());
        out.reverse_pairs.push_back(count_reverse_pairs(data.pairs));
        out.rehearsal_pairs.push_back(rehearsal.size());
        report(progress, phase, k * (1 + static_cast<int>(r.conditions.size())) + 2 + static_cast<int>(c), units);
      }
    }
    result.students.push_back(std::move(r));
  }
  return result;
}

}  // namespace sc
