#include "teaching/sessions/session_analysis.hpp"

namespace sc {

std::vector<ExpertiseTrial> expertise_trials(const TaskKit& kit, const std::vector<TestTrial>& trials) {
  std::vector<StepSequence> steps;
  steps.reserve(trials.size());
  for (const TestTrial& t : trials) steps.push_back(kit.steps_of(t.trial));
  const std::vector<Segmentation> learner = kit.extractor().extract_all(steps);
  std::vector<ExpertiseTrial> out;
  out.reserve(trials.size());
  for (std::size_t i = 0; i < trials.size(); ++i)
    out.push_back({trials[i].scenario, trials[i].expert, learner[i], kit.reward_of(trials[i].trial)});
  return out;
}

ExpertiseEstimate diagnose_trials(const TaskKit& kit, const std::vector<TestTrial>& trials) {
  return estimate_expertise(expertise_trials(kit, trials), kit.extractor().num_skills(),
                            kit.curriculum_config().drills.num_targets);
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
