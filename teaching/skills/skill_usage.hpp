#pragma once
// How an extractor uses its skills over a data set: per skill, how many segments and steps it got and its
// mean segment length (evaluate-skills; a model that puts everything into one or two skills is visible here).
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct SkillUsage {
  int skill = 0;
  int segments = 0;
  int steps = 0;
  double mean_segment_length() const { return segments > 0 ? static_cast<double>(steps) / segments : 0.0; }
};

struct SkillUsageSummary {
  std::vector<SkillUsage> skills;  // only skills with at least one segment, by skill id
  int segments = 0;
  int steps = 0;
  int skills_used() const { return static_cast<int>(skills.size()); }
  double mean_segment_length() const { return segments > 0 ? static_cast<double>(steps) / segments : 0.0; }
};

SkillUsageSummary skill_usage(const std::vector<Segmentation>& segmentations);

// {"skills_used", "segments", "mean_segment_length", "per_skill": [{"skill", "segments", "steps",
// "mean_segment_length"}, ...]}; lengths in the trajectories' own steps.
Json to_json(const SkillUsageSummary& usage);

}  // namespace sc
