#include "teaching/studies/study_report_files.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "teaching/review/review_report.hpp"

namespace sc {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string number(const std::optional<double>& v) { return v ? number(*v) : ""; }

Json json_number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }
Json json_number(const std::optional<double>& v) { return v ? json_number(*v) : Json(nullptr); }

Json summary_json(const stats::SampleSummary& s) {
  return {{"n", s.n},
          {"mean", json_number(s.mean)},
          {"se", json_number(s.se)},
          {"sd", json_number(s.sd)},
          {"min", json_number(s.min)},
          {"q1", json_number(s.q1)},
          {"median", json_number(s.median)},
          {"q3", json_number(s.q3)},
          {"max", json_number(s.max)}};
}

Json comparison_json(const StudyConditionComparison& c) {
  Json j{{"a", c.a},
         {"b", c.b},
         {"n_a", c.n_a},
         {"n_b", c.n_b},
         {"mean_difference", json_number(c.mean_difference)},
         {"tested", c.test.has_value()}};
  if (c.test) {
    j["u"] = c.test->u;
    j["effect"] = c.test->effect;
    j["method"] = std::string(stats::method_description(c.test->method));
    j["z"] = json_number(c.test->z);
    j["ties"] = c.test->ties;
    j["p"] = c.test->p;
    j["p_holm"] = c.p_holm;
    j["significant"] = c.significant;
  }
  return j;
}

Json participant_json(const ParticipantOutcome& p) {
  return {{"seq", p.participant.seq},
          {"learner", p.participant.learner},
          {"condition", p.participant.condition},
          {"enrolled", p.participant.enrolled},
          {"session_id", p.session_id ? Json(*p.session_id) : Json(nullptr)},
          {"pretest_mean", json_number(p.pretest_mean)},
          {"eval_mean", json_number(p.eval_mean)},
          {"improvement", json_number(p.improvement)},
          {"counted", p.counted()},
          {"excluded", p.excluded.empty() ? Json(nullptr) : Json(p.excluded)},
          {"later_sessions", p.later_sessions}};
}

}  // namespace

std::string participants_csv(const StudyAnalysis& analysis) {
  std::ostringstream out;
  out << "seq,learner,condition,enrolled,session_id,pretest_mean,eval_mean,improvement,counted,excluded,"
         "later_sessions\n";
  for (const ParticipantOutcome& p : analysis.participants) {
    out << p.participant.seq << ',' << review::csv_field(p.participant.learner) << ','
        << review::csv_field(p.participant.condition) << ',' << review::csv_field(p.participant.enrolled) << ','
        << (p.session_id ? std::to_string(*p.session_id) : "") << ',' << number(p.pretest_mean) << ','
        << number(p.eval_mean) << ',' << number(p.improvement) << ',' << (p.counted() ? "yes" : "no") << ','
        << review::csv_field(p.excluded) << ',' << p.later_sessions << '\n';
  }
  return out.str();
}

std::string conditions_csv(const StudyAnalysis& analysis) {
  std::ostringstream out;
  out << "condition,name,target,enrolled,n,mean_improvement,se,sd,min,q1,median,q3,max,mean_pretest,mean_eval\n";
  for (const StudyConditionResult& c : analysis.conditions) {
    const auto& s = c.improvement;
    out << review::csv_field(c.condition) << ',' << review::csv_field(c.name) << ',' << c.target << ',' << c.enrolled
        << ',' << s.n << ',' << number(s.mean) << ',' << number(s.se) << ',' << number(s.sd) << ',' << number(s.min)
        << ',' << number(s.q1) << ',' << number(s.median) << ',' << number(s.q3) << ',' << number(s.max) << ','
        << number(c.pretest.mean) << ',' << number(c.eval.mean) << '\n';
  }
  return out.str();
}

std::string comparisons_csv(const StudyAnalysis& analysis) {
  std::ostringstream out;
  out << "a,b,n_a,n_b,mean_difference,u,effect,method,z,p,p_holm,significant\n";
  for (const StudyConditionComparison& c : analysis.comparisons) {
    out << review::csv_field(c.a) << ',' << review::csv_field(c.b) << ',' << c.n_a << ',' << c.n_b << ','
        << number(c.mean_difference) << ',';
    if (c.test) {
      out << number(c.test->u) << ',' << number(c.test->effect) << ','
          << (c.test->method == stats::MannWhitneyMethod::Exact ? "exact" : "normal") << ',' << number(c.test->z) << ','
          << number(c.test->p) << ',' << number(c.p_holm) << ',' << (c.significant ? "yes" : "no") << '\n';
    } else {
      out << ",,not tested,,,,\n";
    }
  }
  return out.str();
}

std::string study_methods_text(const StudyAnalysis& analysis) {
  char alpha[16];
  std::snprintf(alpha, sizeof alpha, "%g", analysis.alpha);
  return "Reward improvement = mean evaluation reward - mean pre-test reward of the participant's first session in "
         "the study (finished, with both scores). Pairs of conditions (" +
         std::string(analysis.plan == ComparisonPlan::Paper ? "the paper's pairs" : "every pair") +
         ") are compared with the two-sided Mann-Whitney U test (exact null distribution when there are no ties and "
         "a condition has at most 8 participants, otherwise the normal approximation with tie and continuity "
         "correction, as scipy.stats.mannwhitneyu) and the p-values are Holm-corrected over the pairs tested; "
         "significant: adjusted p <= " +
         alpha + ".";
}

Json study_report_json(const StudyAnalysis& analysis) {
  const auto& s = analysis.study;
  Json j{{"format", kStudyReportFormat},
         {"version", kStudyReportVersion},
         {"study",
          {{"name", s.name},
           {"task", s.task},
           {"conditions", s.conditions},
           {"target_per_condition", s.target_per_condition},
           {"seed", s.seed},
           {"created", s.created}}},
         {"measure", "reward improvement = mean evaluation reward - mean pre-test reward"},
         {"methods", study_methods_text(analysis)},
         {"plan", analysis.plan == ComparisonPlan::Paper ? "paper" : "all-pairs"},
         {"alpha", analysis.alpha},
         {"conditions", Json::array()},
         {"comparisons", Json::array()},
         {"participants", Json::array()}};
  for (const StudyConditionResult& c : analysis.conditions) {
    j["conditions"].push_back({{"condition", c.condition},
                               {"name", c.name},
                               {"target", c.target},
                               {"enrolled", c.enrolled},
                               {"improvement", summary_json(c.improvement)},
                               {"improvements", c.improvements},
                               {"pretest_mean", json_number(c.pretest.mean)},
                               {"eval_mean", json_number(c.eval.mean)}});
  }
  for (const StudyConditionComparison& c : analysis.comparisons) j["comparisons"].push_back(comparison_json(c));
  for (const ParticipantOutcome& p : analysis.participants) j["participants"].push_back(participant_json(p));
  return j;
}

}  // namespace sc
