#include "teaching/sessions/session_analysis.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace sc {
namespace {

// The references' alignments with the learner run on at most this many points per trace (align_traces_strided):
// at full resolution, ten references added ~2 s to `skillcoach diagnose` of a 3-word writing pre-test.
constexpr int kReferenceAlignPoints = 256;

std::vector<StepSequence> learner_steps(const TaskKit& kit, const std::vector<TestTrial>& trials) {
  std::vector<StepSequence> steps;
  steps.reserve(trials.size());
  for (const TestTrial& t : trials) steps.push_back(kit.steps_of(t.trial));
  return steps;
}

std::vector<ExpertiseTrial> expertise_trials(const TaskKit& kit, const std::vector<TestTrial>& trials,
                                             const std::vector<StepSequence>& steps) {
  const std::vector<Segmentation> learner = kit.extractor().extract_all(steps);
  std::vector<ExpertiseTrial> out;
  out.reserve(trials.size());
  for (std::size_t i = 0; i < trials.size(); ++i)
    out.push_back({trials[i].scenario, trials[i].expert, learner[i], kit.reward_of(trials[i].trial)});
  return out;
}

// The trial document's scenario (null when it has none: steps_of has refused such a trial already).
Json scenario_of(const Json& trial) {
  return trial.is_object() && trial.contains("scenario") ? trial.at("scenario") : Json();
}

}  // namespace

std::vector<ExpertiseTrial> expertise_trials(const TaskKit& kit, const std::vector<TestTrial>& trials) {
  return expertise_trials(kit, trials, learner_steps(kit, trials));
}

ExecutionTrial execution_trial(const TaskKit& kit, const Json& scenario, ExpertiseTrial trial,
                               const StepSequence& expert, const StepSequence& learner, ExpertiseMode mode) {
  ExecutionTrial out{std::move(trial), {}, {}};
  const std::vector<TracePoint3> learner_points = kit.trace_points(learner);
  const StepAlignment path = align_traces(kit.trace_points(expert), learner_points);
  const std::vector<ExecutionReference> references = mode == ExpertiseMode::QualityAware
                                                         ? kit.execution_references(scenario, expert)
                                                         : std::vector<ExecutionReference>{};
  // Each reference is aligned with the learner's trace directly: a learner writing in a reference's hand matches
  // it step by step, where the learner's alignment with the expert (another shape) carried over would not.
  std::vector<StepAlignment> reference_paths;
  for (const ExecutionReference& r : references) {
    out.reference_names.push_back(r.name);
    const std::vector<TracePoint3> points = kit.trace_points(r.steps);
    const auto longest = static_cast<int>(std::max(points.size(), learner_points.size()));
    reference_paths.push_back(
        align_traces_strided(points, learner_points, (longest + kReferenceAlignPoints - 1) / kReferenceAlignPoints));
  }
  for (const SkillSegment& s : out.trial.expert.segments) {
    SegmentExecution e;
    std::tie(e.learner_begin, e.learner_end) = aligned_span(path, s.begin, s.end);
    if (mode == ExpertiseMode::QualityAware)
      e.reward = std::min(kit.execution_reward(expert, learner, path, s.begin, s.end), 0.0);
    for (std::size_t k = 0; k < references.size(); ++k) {
      const auto [begin, end] = aligned_span(references[k].from_expert, s.begin, s.end);
      e.reference_rewards.push_back(
          std::min(kit.execution_reward(references[k].steps, learner, reference_paths[k], begin, end), 0.0));
    }
    out.segments.push_back(e);
  }
  return out;
}

ExpertiseEstimate diagnose_trials(const TaskKit& kit, const std::vector<TestTrial>& trials) {
  if (kit.learners_expertise() != ExpertiseMode::Alg2) return diagnosis_with_places(kit, trials).expertise.estimate;
  // Alg. 2 reads the segmentations alone: no alignment needed.
  return estimate_expertise(expertise_trials(kit, trials), kit.extractor().num_skills(),
                            kit.curriculum_config().drills.num_targets);
}

PlacedDiagnosis diagnosis_with_places(const TaskKit& kit, const std::vector<TestTrial>& trials) {
  const int skills = kit.extractor().num_skills(), targets = kit.curriculum_config().drills.num_targets;
  const std::vector<StepSequence> steps = learner_steps(kit, trials);
  std::vector<ExpertiseTrial> plain = expertise_trials(kit, trials, steps);
  const ExpertiseMode mode = kit.learners_expertise();
  std::vector<ExecutionTrial> evidence;
  for (std::size_t i = 0; i < trials.size(); ++i)
    evidence.push_back(execution_trial(kit, scenario_of(trials[i].trial), std::move(plain[i]), trials[i].expert_steps,
                                       steps[i], mode));
  PlacedDiagnosis out{estimate_execution_expertise(evidence, skills, targets, mode, kit.execution_noise_floor()), {}};
  for (const StepSequence& t : steps) out.learner_steps.push_back(t.length());
  return out;
}

const TargetWhy* charged_why(const PlacedDiagnosis& placed, int skill) {
  const auto& why = placed.expertise.why;
  const auto it = std::find_if(why.begin(), why.end(), [skill](const TargetWhy& w) {
    return w.skill == skill && w.reason != TargetReason::NoMistake;
  });
  return it == why.end() ? nullptr : &*it;
}

std::optional<SkillExample> example_of_skill(const std::vector<ExpertDemo>& pool, int skill) {
  std::optional<SkillExample> best;
  for (std::size_t i = 0; i < pool.size(); ++i)
    for (const SkillSegment& s : pool[i].skills.segments)
      if (s.skill == skill && (!best || s.length() > best->segment.length()))
        best = SkillExample{static_cast<int>(i), s};
  return best;
}

}  // namespace sc
