#include "teaching/tasks/expert_demos.hpp"

#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc {

void segment_expert_demos(std::vector<ExpertDemo>& demos, const SkillExtractor& extractor, int time_slices) {
  const std::vector<StepSequence> steps = demo_steps(demos);
  const std::vector<Segmentation> skills = extractor.extract_all(steps);
  const TimeHeuristicExtractor time_heuristic(time_slices);
  for (std::size_t i = 0; i < demos.size(); ++i) {
    demos[i].skills = skills.at(i);
    demos[i].time_slices = time_heuristic.extract(steps[i]);
  }
}

std::vector<StepSequence> demo_steps(const std::vector<ExpertDemo>& demos) {
  std::vector<StepSequence> out;
  out.reserve(demos.size());
  for (const auto& d : demos) out.push_back(d.steps);
  return out;
}

std::vector<Segmentation> demo_skills(const std::vector<ExpertDemo>& demos) {
  std::vector<Segmentation> out;
  out.reserve(demos.size());
  for (const auto& d : demos) out.push_back(d.skills);
  return out;
}

std::vector<Segmentation> demo_time_slices(const std::vector<ExpertDemo>& demos) {
  std::vector<Segmentation> out;
  out.reserve(demos.size());
  for (const auto& d : demos) out.push_back(d.time_slices);
  return out;
}

}  // namespace sc
