#pragma once
// The analysis step between pre-test and drills: segment the learner's trials with the task's
// SkillExtractor and run Alg. 2 against the expert's segmentation of the same scenarios. Also answers
// "what does skill m look like?" for the diagnosis screen (an expert segment of that skill).
#include <optional>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc {

// A learner's trial with the expert's segmentation of its scenario.
struct TestTrial {
  int scenario = 0;     // id echoed in the diagnosis (pool index for the pre-test, list index for eval)
  Segmentation expert;  // the expert's skills on that scenario
  Json trial;           // the learner's trial document
};

// Segments every learner trial (one batched extractor call) and builds Alg. 2's inputs.
std::vector<ExpertiseTrial> expertise_trials(const TaskKit& kit, const std::vector<TestTrial>& trials);

// Alg. 2 with the kit's skill count and its drill config's N_target.
ExpertiseEstimate diagnose_trials(const TaskKit& kit, const std::vector<TestTrial>& trials);

// An expert segment showing `skill` (the longest one in the pool; ties: lower pool index), for pictures.
struct SkillExample {
  int expert = 0;  // pool index
  SkillSegment segment;
};
std::optional<SkillExample> example_of_skill(const std::vector<ExpertDemo>& pool, int skill);

}  // namespace sc
