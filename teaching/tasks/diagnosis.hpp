#pragma once
// The diagnosis of a learner from their trials, task-agnostic through TaskKit (what `skillcoach diagnose`
// prints and the app's pre-test runs): the skills of each trial and of the expert on the same scenario,
// Alg. 2's expertise vector and N_target targets, and Alg. 3's drills, projected and playable.
#include <cstdint>
#include <vector>

#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc {

struct DiagnosedTrial {
  Json scenario;
  int pool_index = -1;   // the expert pool demo with this scenario, -1 when the expert was planned afresh
  Segmentation expert;   // the extractor on the expert's trial for the scenario
  Segmentation student;  // the extractor on the learner's trial
  double reward = 0.0;   // kit.reward_of(trial), <= 0
};

struct Diagnosis {
  std::vector<DiagnosedTrial> trials;
  ExpertiseEstimate expertise;        // Alg. 2 (targets: N_target of the kit's drill config)
  std::vector<PlayableDrill> drills;  // Alg. 3 for the targets, weakest first, projected by the kit
};

// `trials`: trial documents of the kit's task. Deterministic in `seed` (the random expert segments of the
// drills). InputError for a trial of another task or a malformed trial.
Diagnosis diagnose_trials(const TaskKit& kit, const std::vector<Json>& trials, std::uint64_t seed);

Json segmentation_json(const Segmentation& segmentation);
// {"task", "extractor", "extractor_notice", "trials":[{scenario, pool_index, reward, skills, expert_skills}],
//  "expertise":{...}, "targets":[{skill, expertise, description}], "drills":[{plan..., "skills_described",
//  "steps", "success", "return", "ghost_path", "segment_starts", "trial"}]}
Json diagnosis_json(const TaskKit& kit, const Diagnosis& diagnosis);

}  // namespace sc
