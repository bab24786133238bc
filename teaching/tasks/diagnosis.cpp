#include "teaching/tasks/diagnosis.hpp"

#include "engine/core/error.hpp"
#include "teaching/drills/drill_builder.hpp"
#include "teaching/drills/drill_plan_json.hpp"
#include "teaching/expertise/expertise_json.hpp"
#include "teaching/sessions/session_analysis.hpp"
#include "teaching/tasks/expert_demos.hpp"

namespace sc {

std::vector<DiagnosedTrial> diagnose_each_trial(const TaskKit& kit, const std::vector<Json>& trials,
                                                ExpertiseMode mode) {
  std::vector<DiagnosedTrial> out;
  const std::vector<ExpertDemo>& pool = kit.expert_pool();
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const std::string where = "trial " + std::to_string(i);
    const Json& trial = trials[i];
    if (!trial.is_object() || !trial.contains("task") || trial.at("task") != kit.task())
      throw InputError(where, "$.task: expected \"" + kit.task() + "\"");
    if (!trial.contains("scenario")) throw InputError(where, "$.scenario: missing");
    DiagnosedTrial d;
    d.scenario = trial.at("scenario");
    const Json expert = kit.expert_trial(d.scenario);
    for (std::size_t k = 0; k < pool.size() && d.pool_index < 0; ++k)
      if (pool[k].trial == expert) d.pool_index = static_cast<int>(k);
    const StepSequence expert_steps =
        d.pool_index >= 0 ? pool[static_cast<std::size_t>(d.pool_index)].steps : kit.steps_of(expert);
    d.expert =
        d.pool_index >= 0 ? pool[static_cast<std::size_t>(d.pool_index)].skills : kit.extractor().extract(expert_steps);
    const StepSequence learner_steps = kit.steps_of(trial);
    d.student = kit.extractor().extract(learner_steps);
    d.reward = kit.reward_of(trial);
    ExecutionTrial execution = execution_trial(kit, d.scenario, {static_cast<int>(i), d.expert, d.student, d.reward},
                                               expert_steps, learner_steps, mode);
    d.execution = std::move(execution.segments);
    d.references = std::move(execution.reference_names);
    out.push_back(std::move(d));
  }
  return out;
}

Diagnosis diagnose_trials(const TaskKit& kit, const std::vector<Json>& trials, std::uint64_t seed, ExpertiseMode mode) {
  Diagnosis out;
  out.mode = mode;
  out.trials = diagnose_each_trial(kit, trials, mode);
  std::vector<ExecutionTrial> evidence;
  for (std::size_t i = 0; i < out.trials.size(); ++i) {
    const DiagnosedTrial& d = out.trials[i];
    evidence.push_back({{static_cast<int>(i), d.expert, d.student, d.reward}, d.execution, d.references});
  }
  const CurriculumConfig config = kit.curriculum_config();
  ExecutionExpertise estimate = estimate_execution_expertise(
      evidence, kit.extractor().num_skills(), config.drills.num_targets, mode, kit.execution_noise_floor());
  out.expertise = std::move(estimate.estimate);
  out.why = std::move(estimate.why);
  const DrillBuilder builder(demo_skills(kit.expert_pool()), config.drills);
  Rng rng(seed);
  for (const DrillPlan& plan : builder.individualized(out.expertise, rng))
    out.drills.push_back(kit.projector().project(plan));
  return out;
}

Json segmentation_json(const Segmentation& segmentation) {
  Json out = Json::array();
  for (const SkillSegment& s : segmentation.segments)
    out.push_back({{"skill", s.skill}, {"begin", s.begin}, {"end", s.end}});
  return out;
}

Json diagnosis_json(const TaskKit& kit, const Diagnosis& diagnosis) {
  Json out = {
      {"task", kit.task()}, {"extractor", kit.extractor().name()}, {"extractor_notice", kit.extractor_notice()}};
  Json trials = Json::array();
  for (const DiagnosedTrial& t : diagnosis.trials)
    trials.push_back({{"scenario", t.scenario},
                      {"pool_index", t.pool_index},
                      {"reward", t.reward},
                      {"skills", segmentation_json(t.student)},
                      {"expert_skills", segmentation_json(t.expert)}});
  out["trials"] = std::move(trials);
  out["expertise_mode"] = expertise_mode_name(diagnosis.mode);
  // The floors quality-aware expertise used (none in Alg. 2 mode or for a kit without them).
  const std::optional<NoiseFloor> floor =
      diagnosis.mode == ExpertiseMode::QualityAware ? kit.execution_noise_floor() : std::nullopt;
  const auto value = [](const std::optional<double>& f) { return f ? Json(*f) : Json(nullptr); };
  out["noise_floor"] = floor ? Json(floor->segment) : Json(nullptr);
  out["repeated_noise_floor"] = {{"twice", value(floor ? floor->repeated_twice : std::nullopt)},
                                 {"more", value(floor ? floor->repeated_more : std::nullopt)}};
  out["learner_hand"] =
      diagnosis.expertise.learner_hand.empty() ? Json(nullptr) : Json(diagnosis.expertise.learner_hand);
  out["expertise"] = expertise_to_json(diagnosis.expertise);
  Json targets = Json::array();
  for (std::size_t k = 0; k < diagnosis.expertise.targets.size(); ++k) {
    const int m = diagnosis.expertise.targets[k];
    Json target = {{"skill", m},
                   {"expertise", diagnosis.expertise.expertise[static_cast<std::size_t>(m)]},
                   {"description", kit.describe_skill(m)}};
    if (k < diagnosis.why.size()) {
      const TargetWhy& w = diagnosis.why[k];
      target["why"] = {{"reason", target_reason_words(w.reason)},
                       {"trial", w.trial},
                       {"penalty", w.delta},
                       {"expert_steps", {w.expert_begin, w.expert_end}},
                       {"learner_steps", {w.learner_begin, w.learner_end}}};
    }
    targets.push_back(std::move(target));
  }
  out["targets"] = std::move(targets);
  Json drills = Json::array();
  for (const PlayableDrill& d : diagnosis.drills) {
    Json j = drill_plan_to_json(d.plan);
    Json words = Json::array();
    for (int m : d.plan.ngram) words.push_back(kit.describe_skill(m));
    j["skills_described"] = std::move(words);
    j["steps"] = d.steps.length();
    j["success"] = d.success;
    j["return"] = d.drill_return;
    j["ghost_path"] = d.ghost_path;
    j["segment_starts"] = d.segment_starts;
    j["trial"] = kit.drill_trial(d);
    drills.push_back(std::move(j));
  }
  out["drills"] = std::move(drills);
  return out;
}

}  // namespace sc
