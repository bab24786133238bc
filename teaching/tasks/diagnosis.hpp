#pragma once
// The diagnosis of a learner from their trials, task-agnostic through TaskKit (what `skillcoach diagnose`
// prints and the app's pre-test runs): the skills of each trial and of the expert on the same scenario,
// Alg. 2's expertise vector and N_target targets, and Alg. 3's drills, projected and playable.
#include <cstdint>
#include <vector>

#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc {

struct DiagnosedTrial {
  Json scenario;
  int pool_index = -1;   // the expert pool demo with this scenario, -1 when the expert was planned afresh
  Segmentation expert;   // the extractor on the expert's trial for the scenario
  Segmentation student;  // the extractor on the learner's trial
  double reward = 0.0;   // kit.reward_of(trial), <= 0
  // Per expert segment: the learner's aligned steps and, in quality-aware mode, the task's raw execution
  // score of them (before the learner-relative cut and the noise floor; 0 in Alg. 2 mode).
  std::vector<SegmentExecution> execution;
  std::vector<std::string> references;  // the names of the references execution[k].reference_rewards are against
};

struct Diagnosis {
  std::vector<DiagnosedTrial> trials;
  ExpertiseMode mode = ExpertiseMode::Alg2;
  ExpertiseEstimate expertise;        // Alg. 2 or quality-aware (targets: N_target of the kit's drill config)
  std::vector<TargetWhy> why;         // why each target was chosen and where, parallel to expertise.targets
  std::vector<PlayableDrill> drills;  // Alg. 3 for the targets, weakest first, projected by the kit
};

// `trials`: trial documents of the kit's task. Deterministic in `seed` (the random expert segments of the
// drills). InputError for a trial of another task or a malformed trial. Each expert segment is aligned with
// the learner's trial (dynamic time warping on kit.trace_points) for the "where" of the explanation and, in
// quality-aware mode, scored with kit.execution_reward.
// The per-trial part of diagnose_trials (segmentations, reward, aligned execution), without the expertise
// estimate and the drills: what calibrating the noise floor needs (execution_noise_floor.hpp).
std::vector<DiagnosedTrial> diagnose_each_trial(const TaskKit& kit, const std::vector<Json>& trials,
                                                ExpertiseMode mode);
Diagnosis diagnose_trials(const TaskKit& kit, const std::vector<Json>& trials, std::uint64_t seed,
                          ExpertiseMode mode = ExpertiseMode::Alg2);

Json segmentation_json(const Segmentation& segmentation);
// {"task", "extractor", "extractor_notice", "trials":[{scenario, pool_index, reward, skills, expert_skills}],
//  "expertise_mode":"alg2"|"quality-aware", "noise_floor": the kit's execution noise floor the quality-aware
//  estimate used (null: none, or Alg. 2), "learner_hand": the reference the learner's segments were also
//  scored against (null: the expert's alone), "expertise":{...}, "targets":[{skill, expertise, description,
//  "why":{"reason":"missing"|"done with a large error here"|"no mistake seen", "trial", "penalty", "expert_steps":[b,
//  e], "learner_steps":[b, e]}}], "drills":[{plan..., "skills_described", "steps", "success", "return", "ghost_path",
//  "segment_starts", "trial"}]}
Json diagnosis_json(const TaskKit& kit, const Diagnosis& diagnosis);

}  // namespace sc
