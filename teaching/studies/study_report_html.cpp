#include "teaching/studies/study_report_html.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "teaching/review/review_report.hpp"
#include "teaching/studies/study_report_files.hpp"

namespace sc {
namespace {

using review::html_escape;

constexpr const char* kStyle = R"(
body{font-family:"DejaVu Sans",Verdana,sans-serif;background:#fff;color:#1e2126;margin:0;padding:24px 40px;
line-height:1.45;max-width:1200px}
h1{font-size:26px;margin:0 0 4px}
h2{font-size:20px;margin:30px 0 8px;border-bottom:1px solid #d5d9df;padding-bottom:4px}
p.note{color:#5f6670;margin:4px 0}
table{border-collapse:collapse;margin:8px 0 16px;font-size:14px}
th,td{padding:4px 10px;border-bottom:1px solid #e3e6ea;text-align:left}
th{color:#5f6670;font-weight:600} td.num{text-align:right;font-variant-numeric:tabular-nums}
.sig{font-weight:700;color:#0b6e4f} .muted{color:#8a929c}
figure{margin:10px 0 20px} figure img{max-width:100%;height:auto;border:1px solid #e3e6ea}
figcaption{color:#5f6670;font-size:14px;margin-top:6px}
)";

std::string fixed(double v, const char* format = "%.4f") {
  if (!std::isfinite(v)) return "";
  char text[40];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

void definition(std::ostringstream& h, const StudyAnalysis& a) {
  const auto& s = a.study;
  h << "<p class=note>Task <b>" << html_escape(s.task) << "</b>; " << s.conditions.size() << " conditions, target "
    << s.target_per_condition << " participants each; randomisation seed " << s.seed << "; created "
    << html_escape(s.created) << ". " << a.participants.size() << " enrolled, " << a.counted() << " counted.</p>\n";
}

void condition_table(std::ostringstream& h, const StudyAnalysis& a) {
  h << "<h2>Reward improvement per condition</h2>\n<table><tr><th>Condition</th><th>N</th><th>Enrolled / target</th>"
       "<th>Mean &plusmn; s.e.</th><th>SD</th><th>Median [Q1, Q3]</th><th>Pre-test</th><th>Evaluation</th></tr>\n";
  for (const StudyConditionResult& c : a.conditions) {
    const auto& s = c.improvement;
    h << "<tr><td>" << html_escape(c.name) << "</td><td class=num>" << s.n << "</td><td class=num>" << c.enrolled
      << " / " << c.target << "</td><td class=num>" << fixed(s.mean) << (std::isfinite(s.se) ? " &plusmn; " : "")
      << fixed(s.se) << "</td><td class=num>" << fixed(s.sd) << "</td><td class=num>" << fixed(s.median)
      << (s.n > 0 ? " [" + fixed(s.q1) + ", " + fixed(s.q3) + "]" : "") << "</td><td class=num>"
      << fixed(c.pretest.mean) << "</td><td class=num>" << fixed(c.eval.mean) << "</td></tr>\n";
  }
  h << "</table>\n";
}

void comparison_table(std::ostringstream& h, const StudyAnalysis& a) {
  h << "<h2>Between conditions</h2>\n<table><tr><th>Pair</th><th>N</th><th>Difference of means</th><th>U</th>"
       "<th>P(a &gt; b)</th><th>Method</th><th>p</th><th>p (Holm)</th></tr>\n";
  for (const StudyConditionComparison& c : a.comparisons) {
    h << "<tr><td>" << html_escape(condition_display_name(c.a)) << " vs " << html_escape(condition_display_name(c.b))
      << "</td><td class=num>" << c.n_a << " / " << c.n_b << "</td><td class=num>" << fixed(c.mean_difference, "%+.4f")
      << "</td>";
    if (!c.test) {
      h << "<td colspan=5 class=muted>not tested: a condition has no counted participant</td></tr>\n";
      continue;
    }
    h << "<td class=num>" << fixed(c.test->u, "%g") << "</td><td class=num>" << fixed(c.test->effect, "%.2f")
      << "</td><td>" << (c.test->method == stats::MannWhitneyMethod::Exact ? "exact" : "normal approx.")
      << "</td><td class=num>" << format_p(c.test->p) << "</td><td class=\"num" << (c.significant ? " sig\">" : "\">")
      << format_p(c.p_holm) << (c.significant ? " *" : "") << "</td></tr>\n";
  }
  h << "</table>\n<p class=note>" << html_escape(study_methods_text(a))
    << " U is the first condition's statistic; P(a &gt; b) = U / (n<sub>a</sub> n<sub>b</sub>).</p>\n";
}

void participant_table(std::ostringstream& h, const StudyAnalysis& a) {
  h << "<h2>Participants</h2>\n<table><tr><th>#</th><th>Learner</th><th>Condition</th><th>Session</th>"
       "<th>Pre-test</th><th>Evaluation</th><th>Improvement</th><th>Counted</th></tr>\n";
  for (const ParticipantOutcome& p : a.participants) {
    h << "<tr><td class=num>" << p.participant.seq << "</td><td>" << html_escape(p.participant.learner) << "</td><td>"
      << html_escape(condition_display_name(p.participant.condition)) << "</td><td class=num>"
      << (p.session_id ? std::to_string(*p.session_id) : "") << "</td><td class=num>"
      << (p.pretest_mean ? fixed(*p.pretest_mean) : "") << "</td><td class=num>"
      << (p.eval_mean ? fixed(*p.eval_mean) : "") << "</td><td class=num>"
      << (p.improvement ? fixed(*p.improvement, "%+.4f") : "") << "</td><td"
      << (p.counted() ? ">yes" : " class=muted>no: " + html_escape(p.excluded))
      << (p.later_sessions > 0 ? " (" + std::to_string(p.later_sessions) + " later session(s) ignored)" : "")
      << "</td></tr>\n";
  }
  h << "</table>\n";
}

}  // namespace

std::string format_p(double p) {
  if (!std::isfinite(p)) return "";
  if (p < 0.0001) return "< 0.0001";
  return fixed(p, "%.4f");
}

std::string study_report_html(const StudyAnalysis& analysis, const StudyReportPlot& plot) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>Study " << html_escape(analysis.study.name)
    << "</title>\n<style>" << kStyle << "</style></head><body>\n<h1>Study: " << html_escape(analysis.study.name)
    << "</h1>\n";
  definition(h, analysis);
  condition_table(h, analysis);
  h << "<figure><img alt=\"reward improvement per condition\" src=\"data:image/png;base64,"
    << review::base64(plot.png_bytes) << "\"><figcaption>Each point is one participant (" << html_escape(plot.file)
    << "): box = quartiles, whiskers = the furthest values within 1.5 IQR, black bar = mean &plusmn; s.e.</figcaption>"
       "</figure>\n";
  comparison_table(h, analysis);
  participant_table(h, analysis);
  h << "<p class=note>Written by <code>skillcoach study-report</code>; the numbers are in conditions.csv, "
       "comparisons.csv, participants.csv and study_report.json next to this page.</p>\n</body></html>\n";
  return h.str();
}

}  // namespace sc
