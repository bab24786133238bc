#include "teaching/curricula/adaptive_curriculum.hpp"

#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "teaching/expertise/latest_evidence.hpp"

namespace sc {
namespace {

constexpr std::uint64_t kAdaptiveStream = 1000;  // rounds fork Rng streams 1000, 1001, ... (conditions use 0..5)

int round_budget(const CurriculumInputs& inputs, const CurriculumConfig& config) {
  const int total = curriculum_budget_steps(inputs, config);
  return (total + config.adaptive_rounds - 1) / config.adaptive_rounds;
}

AdaptiveRound make_round(std::size_t index, ExpertiseEstimate evidence, ExpertiseEstimate diagnosis,
                         const CurriculumInputs& inputs, const CurriculumConfig& config) {
  AdaptiveRound round;
  if (config.budget_steps > 0) {
    Rng rng = Rng(inputs.seed).fork(kAdaptiveStream + index);
    round.practice = individualized_drill_curriculum(StudyCondition::Adaptive, diagnosis, round_budget(inputs, config),
                                                     inputs, config, rng);
  } else {
    // The first round draws what Ind. Drills draws, so the two arms differ only in the later rounds.
    Rng rng =
        index == 0 ? curriculum_rng(inputs, StudyCondition::IndDrills) : Rng(inputs.seed).fork(kAdaptiveStream + index);
    round.practice = weak_skill_round(StudyCondition::Adaptive, diagnosis, inputs, config, rng);
  }
  round.evidence = std::move(evidence);
  round.diagnosis = std::move(diagnosis);
  return round;
}

}  // namespace

AdaptiveRound first_adaptive_round(const CurriculumInputs& inputs, const CurriculumConfig& config) {
  return make_round(0, inputs.pretest, inputs.pretest, inputs, config);
}

AdaptiveRound next_round(const std::vector<AdaptiveRound>& previous, const std::vector<ExpertiseTrial>& new_trials,
                         const CurriculumInputs& inputs, const CurriculumConfig& config) {
  if (previous.empty())
    throw InputError("adaptive curriculum", "next_round needs the previous rounds (start with first_adaptive_round)");
  const int skills = previous.front().evidence.num_skills();
  ExpertiseEstimate evidence = estimate_expertise(new_trials, skills, config.drills.num_targets);
  std::vector<ExpertiseEstimate> rounds;
  rounds.reserve(previous.size() + 1);
  for (const auto& r : previous) rounds.push_back(r.evidence);
  rounds.push_back(evidence);
  ExpertiseEstimate diagnosis = latest_evidence_expertise(rounds, config.drills.num_targets);
  return make_round(previous.size(), std::move(evidence), std::move(diagnosis), inputs, config);
}

ExpertiseTrial practice_trial(const PracticeItem& item, Segmentation learner, double reward, int scenario) {
  return ExpertiseTrial{scenario, plan_segmentation(item.material), std::move(learner), reward};
}

}  // namespace sc
