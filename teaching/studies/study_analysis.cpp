#include "teaching/studies/study_analysis.hpp"

#include <cmath>
#include <limits>

#include "engine/core/error.hpp"
#include "teaching/curricula/study_condition.hpp"
#include "teaching/stats/holm_correction.hpp"

namespace sc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

StudyConditionResult condition_result(const records::StudyDefinition& study, const std::string& condition,
                                      const std::vector<ParticipantOutcome>& participants) {
  StudyConditionResult r;
  r.condition = condition;
  r.name = condition_display_name(condition);
  r.target = study.target_per_condition;
  std::vector<double> pretest, eval;
  for (const ParticipantOutcome& p : participants) {
    if (p.participant.condition != condition) continue;
    ++r.enrolled;
    if (!p.counted()) continue;
    r.improvements.push_back(*p.improvement);
    pretest.push_back(*p.pretest_mean);
    eval.push_back(*p.eval_mean);
  }
  r.improvement = stats::summarise(r.improvements);
  r.pretest = stats::summarise(pretest);
  r.eval = stats::summarise(eval);
  return r;
}

const StudyConditionResult& result_of(const std::vector<StudyConditionResult>& results, const std::string& condition) {
  for (const StudyConditionResult& r : results)
    if (r.condition == condition) return r;
  throw InputError("study analysis", "no condition \"" + condition + "\"");  // planned pairs come from the study
}

}  // namespace

int StudyAnalysis::counted() const {
  int n = 0;
  for (const StudyConditionResult& c : conditions) n += c.improvement.n;
  return n;
}

std::string condition_display_name(const std::string& key) {
  try {
    return std::string(condition_name(parse_condition(key)));
  } catch (const InputError&) {
    return key;
  }
}

StudyAnalysis analyse_study(const records::StudyDefinition& study, std::vector<ParticipantOutcome> participants,
                            ComparisonPlan plan, double alpha) {
  StudyAnalysis analysis{study, std::move(participants), {}, {}, plan, alpha};
  for (const std::string& condition : study.conditions)
    analysis.conditions.push_back(condition_result(study, condition, analysis.participants));
  std::vector<double> p_values;
  for (const auto& [a, b] : planned_comparisons(study.conditions, plan)) {
    const StudyConditionResult& ra = result_of(analysis.conditions, a);
    const StudyConditionResult& rb = result_of(analysis.conditions, b);
    StudyConditionComparison c{a, b, ra.improvement.n, rb.improvement.n, kNaN, std::nullopt, kNaN, false};
    if (c.n_a > 0 && c.n_b > 0) {
      c.mean_difference = ra.improvement.mean - rb.improvement.mean;
      c.test = stats::mann_whitney_u(ra.improvements, rb.improvements);
      p_values.push_back(c.test->p);
    }
    analysis.comparisons.push_back(c);
  }
  // Holm over the tests actually run (a pair without participants is not part of the family).
  const std::vector<double> adjusted = stats::holm_adjusted(p_values);
  std::size_t next = 0;
  for (StudyConditionComparison& c : analysis.comparisons) {
    if (!c.test) continue;
    c.p_holm = adjusted[next++];
    c.significant = c.p_holm <= alpha;
  }
  return analysis;
}

}  // namespace sc
