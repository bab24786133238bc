#pragma once
// Shared by the task kits: segmenting an expert pool once with the kit's SkillExtractor and with the
// paper's time heuristic, and the views of the pool other teaching code takes as plain vectors.
#include <vector>

#include "teaching/sessions/task_kit.hpp"

namespace sc {

// Fills `skills` (extractor, batched) and `time_slices` (TimeHeuristicExtractor with K = time_slices) of
// every demo; `steps` must already be set. K: 3 for parking, 8 for writing (the paper's study).
void segment_expert_demos(std::vector<ExpertDemo>& demos, const SkillExtractor& extractor, int time_slices);

std::vector<StepSequence> demo_steps(const std::vector<ExpertDemo>& demos);
std::vector<Segmentation> demo_skills(const std::vector<ExpertDemo>& demos);
std::vector<Segmentation> demo_time_slices(const std::vector<ExpertDemo>& demos);

}  // namespace sc
