#include "teaching/sessions/session_summary.hpp"

#include <algorithm>
#include <cmath>

namespace sc {

SkillTrend skill_trend(const SkillChange& change) {
  const auto shown = [](double e) { return std::lround(e * 100.0); };  // in hundredths, as printed
  const long before = shown(change.before), after = shown(change.after);
  if (before == 0 && after == 0) return SkillTrend::no_mistake;
  if (after == before) return SkillTrend::same;
  return after > before ? SkillTrend::better : SkillTrend::worse;
}

const char* to_string(SkillTrend trend) {
  switch (trend) {
    case SkillTrend::no_mistake:
      return "no mistake";
    case SkillTrend::better:
      return "better";
    case SkillTrend::same:
      return "same";
    case SkillTrend::worse:
      return "worse";
  }
  return "?";
}

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
