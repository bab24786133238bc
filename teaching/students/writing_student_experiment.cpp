#include "teaching/students/writing_student_experiment.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/writing/writing_scenario.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/students/bc_datasets.hpp"
#include "teaching/students/experiment_seeds.hpp"
#include "teaching/students/finetune_data.hpp"
#include "teaching/students/writing_pen_policy.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {
namespace {

using namespace experiment_seeds;  // NOLINT: the streams and derived_seed, shared with the other task

void report(const ExperimentProgress& progress, const std::string& phase, int done, int total) {
  if (progress) progress(phase, done, total);
}

// Per pool word, the symbol of every expert step (true character bounds).
std::vector<std::vector<char>> step_symbols(const std::vector<writing::WordTrajectory>& words) {
  std::vector<std::vector<char>> out;
  for (const writing::WordTrajectory& w : words) out.push_back(labelled_pen_pairs({w}).symbol);
  return out;
}

// Pairs of `letter` among the first data.pairs.size() pairs the items hold (finetune_data's order).
int letter_pairs_of(const FinetuneData& data, const std::vector<std::vector<char>>& symbols, char letter) {
  int seen = 0, letters = 0;
  for (const PracticeItem& item : data.items)
    for (int k = 0; k < item.sessions; ++k)
      for (const DrillSegment& s : item.material.segments)
        for (int t = s.begin; t < s.end && seen < data.pairs.size(); ++t, ++seen)
          letters += symbols[static_cast<std::size_t>(s.expert)][static_cast<std::size_t>(t)] == letter;
  return letters;
}

std::vector<writing::WordTrajectory> evaluation_words(const WritingKit& kit, int count, std::uint64_t seed,
                                                      std::vector<std::string>& names) {
  std::vector<Json> pool;
  for (const ExpertDemo& d : kit.expert_pool()) pool.push_back(d.scenario);
  std::vector<writing::WordTrajectory> out;
  for (const Json& doc : kit.fresh_scenarios(count, seed, pool)) {
    const writing::WritingScenario scenario = writing::parse_writing_scenario(JsonView(doc, "fresh word"));
    names.push_back(scenario.word);
    out.push_back(writing::gold_trajectory(scenario));
  }
  if (static_cast<int>(out.size()) < count)
    throw InputError("writing students", "the alphabet has too few fresh words");
  return out;
}

// Alg. 2 on the CompILE segmentation of the student's own traces of the diagnosis words.
void diagnose(const WritingKit& kit, const std::vector<int>& picks, int num_targets, const BcPolicy& policy,
              WritingStudentResult& out) {
  std::vector<ExpertiseTrial> trials;
  for (int pick : picks) {
    const writing::WordTrajectory& gold = kit.gold_words()[static_cast<std::size_t>(pick)];
    writing::WritingTrial trial;
    trial.scenario = {gold.word, gold.alphabet, {}};
    trial.points = rollout_pen(policy, gold);
    trial.source = "student";
    const double reward = pen_trace_reward(gold, trial.points);
    out.diagnosis_reward += reward / static_cast<double>(picks.size());
    trials.push_back({pick, kit.expert_pool()[static_cast<std::size_t>(pick)].skills,
                      kit.extractor().extract(writing_step_sequence(trial)), reward});
  }
  out.diagnosis = estimate_expertise(trials, kit.extractor().num_skills(), num_targets);
}

struct SetContext {
  int index = 0;
  const std::vector<writing::WordTrajectory>* words = nullptr;
};

void finetune_set(const WritingStudentExperimentConfig& config, const WritingStudent& student, std::size_t s,
                  const FinetuneMaterial& material, const std::vector<std::vector<char>>& symbols,
                  const SetContext& set, WritingStudentResult& r) {
  const auto k = static_cast<std::uint64_t>(set.index);
  const std::uint64_t data_seed = derived_seed(config.seed, kFinetuneData, k);
  const int pairs = config.finetune_pairs > 0 ? config.finetune_pairs : individualized_round_pairs(material, data_seed);
  const int own = static_cast<int>(std::lround(config.finetune_rehearsal * pairs));
  const BcDataset rehearsal = sample_pairs(student.training_data, own, derived_seed(config.seed, kRehearsal, s, k));
  for (WritingConditionResult& out : r.conditions) {
    const FinetuneData data = finetune_data(out.condition, material, pairs, data_seed);
    BcDataset training_pairs = pen_dataset(data.pairs);
    if (own > 0) training_pairs.append(rehearsal);
    BcPolicy copy = student.policy.clone();
    BcTrainingConfig training;
    training.epochs = config.finetune_epochs;
    training.learning_rate = config.finetune_learning_rate;
    training.batch_size = student.recipe.batch_size;
    training.seed = derived_seed(config.seed, kFinetuneTraining, s, k);  // same for every condition: paired
    out.finetune_loss.push_back(copy.train(training_pairs, training));
    out.reward.push_back(score_pen_student(copy, *set.words));
    out.pairs.push_back(data.pairs.size());
    out.letter_pairs.push_back(
        student.recipe.deficit == PenDeficit::HalfTrained ? 0 : letter_pairs_of(data, symbols, student.recipe.letter));
    out.rehearsal_pairs.push_back(rehearsal.size());
  }
}

}  // namespace

WritingStudentExperimentConfig WritingStudentExperimentConfig::standard() {
  WritingStudentExperimentConfig c;
  c.students = WritingStudentRecipe::defaults(30);
  return c;
}

WritingStudentExperimentConfig WritingStudentExperimentConfig::quick() {
  WritingStudentExperimentConfig c;
  c.students = WritingStudentRecipe::defaults(2);
  c.students = {c.students[0], c.students.back()};  // missing 'a', half-trained
  for (WritingStudentRecipe& r : c.students) r.hidden = 16;
  c.diagnosis_words = 2;
  c.finetune_epochs = 1;
  c.evaluation_sets = 3;
  c.words_per_set = 1;
  return c;
}

void WritingStudentExperimentConfig::validate() const {
  auto in_range = [](int v, int lo, int hi, const char* name) {
    if (v < lo || v > hi)
      throw InputError("writing students", std::string(name) + " must lie in [" + std::to_string(lo) + ", " +
                                               std::to_string(hi) + "], got " + std::to_string(v));
  };
  in_range(static_cast<int>(students.size()), 1, 64, "the number of students");
  in_range(diagnosis_words, 1, 1000, "diagnosis_words");
  in_range(num_targets, 1, 100, "num_targets");
  in_range(finetune_epochs, 1, 100000, "finetune_epochs");
  in_range(finetune_pairs, 0, 10000000, "finetune_pairs");
  in_range(evaluation_sets, 1, 1000, "evaluation_sets");
  in_range(words_per_set, 1, 30, "words_per_set");
  if (!(finetune_learning_rate > 0.0 && finetune_learning_rate <= 1.0))
    throw InputError("writing students",
                     "finetune_learning_rate must lie in (0, 1], got " + std::to_string(finetune_learning_rate));
  if (!(finetune_rehearsal >= 0.0 && finetune_rehearsal <= 100.0))
    throw InputError("writing students",
                     "finetune_rehearsal must lie in [0, 100], got " + std::to_string(finetune_rehearsal));
  for (const WritingStudentRecipe& r : students) {
    in_range(r.epochs, 1, 100000, "student epochs");
    in_range(r.hidden, 1, 4096, "student hidden width");
  }
}

const WritingConditionResult& WritingStudentResult::of(StudyCondition condition) const {
  for (const WritingConditionResult& c : conditions)
    if (c.condition == condition) return c;
  throw InputError("writing students", std::string(condition_name(condition)) + " was not run");
}

WritingStudentExperimentResult run_writing_student_experiment(const WritingKit& kit,
                                                              const WritingStudentExperimentConfig& config,
                                                              const ExperimentProgress& progress) {
  config.validate();
  if (kit.gold_words().empty() || kit.gold_words().front().alphabet != writing::AlphabetKind::Classic)
    throw InputError("writing students", "the experiment needs the classic-alphabet writing kit");
  configure_torch_threads();
  WritingStudentExperimentResult result;
  result.config = config;
  result.extractor = kit.extractor().name();
  result.extractor_notice = kit.extractor_notice();
  result.pool_size = static_cast<int>(kit.gold_words().size());
  const LabelledPenPairs expert = labelled_pen_pairs(kit.gold_words());
  const std::vector<std::vector<char>> symbols = step_symbols(kit.gold_words());
  result.expert_pairs = expert.pairs.size();
  result.diagnosis_words = select_diverse_scenarios(demo_skills(kit.expert_pool()), config.diagnosis_words).scenarios();
  std::vector<std::vector<writing::WordTrajectory>> sets;
  for (int k = 0; k < config.evaluation_sets; ++k) {
    result.evaluation_words.emplace_back();
    sets.push_back(evaluation_words(kit, config.words_per_set, derived_seed(config.seed, kEvaluationSet, k),
                                    result.evaluation_words.back()));
  }
  for (std::size_t s = 0; s < config.students.size(); ++s) {
    const WritingStudentRecipe& recipe = config.students[s];
    const std::string name = recipe.name();
    report(progress, "training " + name, 0, 1);
    const WritingStudent student = train_writing_student(recipe, expert, derived_seed(config.seed, kStudentInit, s));
    WritingStudentResult r;
    r.recipe = recipe;
    r.training_pairs = student.training_data.size();
    r.letter_pairs = student.letter_pairs;
    r.training_loss = student.training_loss;
    r.expert_mse = student.expert_mse;
    diagnose(kit, result.diagnosis_words, config.num_targets, student.policy, r);
    const FinetuneMaterial material{demo_steps(kit.expert_pool()), demo_skills(kit.expert_pool()), r.diagnosis,
                                    config.num_targets};
    for (StudyCondition c : kFinetuneConditions) r.conditions.push_back(WritingConditionResult{c, {}, {}, {}, {}, {}});
    for (int k = 0; k < config.evaluation_sets; ++k) {
      r.before_reward.push_back(score_pen_student(student.policy, sets[static_cast<std::size_t>(k)]));
      finetune_set(config, student, s, material, symbols, {k, &sets[static_cast<std::size_t>(k)]}, r);
      report(progress, "fine-tuning " + name, k + 1, config.evaluation_sets);
    }
    result.students.push_back(std::move(r));
  }
  return result;
}

}  // namespace sc
