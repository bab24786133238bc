#include "teaching/sessions/session_summary.hpp"

#include <algorithm>

namespace sc {

double mean_of(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

RoundSummary summarize_round(int round, const std::vector<double>& pretest_rewards,
                             const std::vector<double>& eval_rewards, const ExpertiseEstimate& before,
                             const ExpertiseEstimate& after, const std::map<int, int>& trials_per_skill,
                             int practice_trials) {
  RoundSummary summary;
  summary.round = round;
  summary.pretest_mean = mean_of(pretest_rewards);
  summary.eval_mean = mean_of(eval_rewards);
  summary.improvement = summary.eval_mean - summary.pretest_mean;
  summary.practice_trials = practice_trials;
  const int skills = std::max(before.num_skills(), after.num_skills());
  for (int m = 0; m < skills; ++m) {
    SkillChange change;
    change.skill = m;
    const auto at = [m](const ExpertiseEstimate& e, const std::vector<double>& v) {
      return m < e.num_skills() ? v[static_cast<std::size_t>(m)] : 0.0;
    };
    change.before = at(before, before.expertise);
    change.after = at(after, after.expertise);
    const auto occurs = [m](const ExpertiseEstimate& e) {
      return m < e.num_skills() && e.occurrences[static_cast<std::size_t>(m)] > 0;
    };
    change.seen = occurs(before) || occurs(after);
    const auto practised = trials_per_skill.find(m);
    change.practice_trials = practised == trials_per_skill.end() ? 0 : practised->second;
    change.drilled = change.practice_trials > 0;
    summary.skills.push_back(change);
  }
  return summary;
}

}  // namespace sc
