#pragma once
// The analysis step between pre-test and drills: segment the learner's trials with the task's
// SkillExtractor and estimate expertise against the expert's segmentation of the same scenarios (Alg. 2,
// or quality-aware expertise where the kit's learners_expertise() says so). Also answers "what does skill
// m look like?" for the diagnosis screen (an expert segment of that skill).
#include <optional>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc {

// A learner's trial with the expert's segmentation of its scenario.
struct TestTrial {
  int scenario = 0;           // id echoed in the diagnosis (pool index for the pre-test, list index for eval)
  Segmentation expert;        // the expert's skills on that scenario
  Json trial;                 // the learner's trial document
  StepSequence expert_steps;  // the expert's steps on that scenario (quality-aware expertise aligns with them)
};

// Segments every learner trial (one batched extractor call) and builds Alg. 2's inputs.
std::vector<ExpertiseTrial> expertise_trials(const TaskKit& kit, const std::vector<TestTrial>& trials);

// One trial's evidence for quality-aware expertise: `trial` (Alg. 2's) plus, per expert segment, the
// learner's steps aligned with it and (mode QualityAware) the kit's execution score of that part, against
// the expert and against each of the kit's execution_references for `scenario`.
ExecutionTrial execution_trial(const TaskKit& kit, const Json& scenario, ExpertiseTrial trial,
                               const StepSequence& expert, const StepSequence& learner, ExpertiseMode mode);

// The kit's learners_expertise() with the kit's skill count and its drill config's N_target.
ExpertiseEstimate diagnose_trials(const TaskKit& kit, const std::vector<TestTrial>& trials);
// The same estimate, with why each target was chosen and where (TargetWhy: the trial, the expert's segment and the
// learner's steps aligned with it), for the diagnosis page's pictures, and each trial's step count (to find those
// steps on the trial's path). Aligns every trial also under Alg. 2.
struct PlacedDiagnosis {
  ExecutionExpertise expertise;
  std::vector<int> learner_steps;  // per trial
};
PlacedDiagnosis diagnosis_with_places(const TaskKit& kit, const std::vector<TestTrial>& trials);
// `skill`'s largest penalty in `placed` (where it went wrong), or null when it has none (a target by rank alone).
const TargetWhy* charged_why(const PlacedDiagnosis& placed, int skill);

// An expert segment showing `skill` (the longest one in the pool; ties: lower pool index), for pictures.
struct SkillExample {
  int expert = 0;  // pool index
  SkillSegment segment;
};
std::optional<SkillExample> example_of_skill(const std::vector<ExpertDemo>& pool, int skill);

}  // namespace sc
