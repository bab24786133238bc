// skillcoach study-report: a study's result from the learner store (read-only) - per condition the reward
// improvement's mean +- s.e. and N, the paper's pairwise Mann-Whitney U tests with Holm's correction
// (teaching/studies/study_analysis.hpp), written as participants.csv, conditions.csv, comparisons.csv,
// study_report.json, a strip + box plot (improvement_<task>.png) and the self-contained study_report.html.
// An unknown study, a study without a counted session or an unreadable store: one line, exit 2.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "engine/core/atomic_file.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/strip_box_chart_image.hpp"
#include "teaching/curricula/study_condition.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/studies/study_report_files.hpp"
#include "teaching/studies/study_report_html.hpp"

namespace sc::cli {
namespace {

namespace fs = std::filesystem;

struct StudyReportOptions {
  std::string store;
  std::string study;
  std::string out;
  std::string pairs = "paper";
  double alpha = 0.05;
};

// One colour per condition, the same in every report.
Color condition_color(const std::string& key) {
  try {
    switch (parse_condition(key)) {
      case StudyCondition::FullTrajectory:
        return Color::hex(0x8c96a3);
      case StudyCondition::TimeHeuristic:
        return Color::hex(0xe0833a);
      case StudyCondition::Skills:
        return Color::hex(0xd1496b);
      case StudyCondition::Drills:
        return Color::hex(0x2f80ed);
      case StudyCondition::IndDrills:
        return Color::hex(0x3a8f5c);
      case StudyCondition::Adaptive:
        return Color::hex(0x7b4fc9);
    }
  } catch (const InputError&) {}
  return Color::hex(0x3a3f47);
}

StripBoxFigure figure_of(const StudyAnalysis& a) {
  StripBoxFigure f;
  f.title = "Study \"" + a.study.name + "\" (" + a.study.task + "): reward improvement per participant";
  f.panel_title = "mean evaluation reward - mean pre-test reward";
  f.notes = {
      "Points: participants. Box: quartiles and median; whiskers: furthest values within 1.5 IQR. "
      "Black: mean +- standard error."};
  for (const StudyConditionResult& c : a.conditions) {
    const auto& s = c.improvement;
    f.groups.push_back({c.name, "N = " + std::to_string(s.n) + " of " + std::to_string(c.target),
                        condition_color(c.condition), c.improvements, s.q1, s.median, s.q3, s.whisker_low,
                        s.whisker_high, s.mean, s.se});
  }
  return f;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void print_summary(const StudyAnalysis& a) {
  std::printf("study \"%s\" (%s): %zu enrolled, %d counted\n", a.study.name.c_str(), a.study.task.c_str(),
              a.participants.size(), a.counted());
  std::printf("  %-16s %4s %10s %9s\n", "condition", "N", "mean", "s.e.");
  for (const StudyConditionResult& c : a.conditions)
    std::printf("  %-16s %4d %+10.4f %9.4f\n", c.name.c_str(), c.improvement.n, c.improvement.mean, c.improvement.se);
  for (const StudyConditionComparison& c : a.comparisons) {
    const std::string pair = condition_display_name(c.a) + " vs " + condition_display_name(c.b);
    if (!c.test) {
      std::printf("  %-34s not tested (a condition has no counted participant)\n", pair.c_str());
      continue;
    }
    std::printf("  %-34s U = %6g  p = %-8s p(Holm) = %-8s %s%s\n", pair.c_str(), c.test->u, format_p(c.test->p).c_str(),
                format_p(c.p_holm).c_str(), c.test->method == stats::MannWhitneyMethod::Exact ? "exact" : "normal",
                c.significant ? "  *" : "");
  }
}

int run(const StudyReportOptions& o) {
  const auto opened = records::open_record_store(o.store, records::StoreOptions{.read_only = true});
  const records::RecordStore& store = *opened;
  const std::string db = store.database_path().string();
  const auto study = store.study(o.study);
  if (!study) throw InputError(db, "has no study \"" + o.study + "\"");
  auto outcomes = participant_outcomes(store.study_participants(o.study), store.study_sessions(o.study));
  const StudyAnalysis analysis = analyse_study(
      *study, std::move(outcomes), o.pairs == "all" ? ComparisonPlan::AllPairs : ComparisonPlan::Paper, o.alpha);
  if (analysis.counted() == 0)
    throw InputError(db, "study \"" + o.study + "\" has no finished session with pre-test and evaluation scores yet (" +
                             std::to_string(analysis.participants.size()) + " enrolled)");
  const fs::path out(o.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw InputError(o.out, "cannot create the output folder (" + ec.message() + ")");
  write_file_atomically(out / "participants.csv", participants_csv(analysis));
  write_file_atomically(out / "conditions.csv", conditions_csv(analysis));
  write_file_atomically(out / "comparisons.csv", comparisons_csv(analysis));
  write_file_atomically(out / "study_report.json", study_report_json(analysis).dump(1) + "\n");
  const StripBoxFigure figure = figure_of(analysis);
  const std::string png = "improvement_" + analysis.study.task + ".png";
  auto context = create_offscreen_context_from_env(figure.width, figure.height);
  write_png(out / png, render_strip_box_figure(*context, figure));
  write_file_atomically(out / "study_report.html", study_report_html(analysis, {png, read_bytes(out / png)}));
  print_summary(analysis);
  std::printf(
      "wrote participants.csv, conditions.csv, comparisons.csv, study_report.json, %s and study_report.html "
      "to %s\n",
      png.c_str(), o.out.c_str());
  return 0;
}

CommandRunner setup_study_report(CLI::App& sub) {
  auto o = std::make_shared<StudyReportOptions>();
  sub.add_option("--store", o->store,
                 "Data directory, its skillcoach.db, or a postgresql:// URL (a shared server; see docs/database.md) "
                 "(default: $XDG_DATA_HOME/skillcoach or ~/.local/share/skillcoach)");
  sub.add_option("--study", o->study, "The study")->required();
  sub.add_option("--out", o->out, "Folder to write the report into (created)")->required();
  sub.add_option("--pairs", o->pairs, "paper: the paper's pairs present in the study (default); all: every pair")
      ->check(CLI::IsMember({"paper", "all"}))
      ->capture_default_str();
  sub.add_option("--alpha", o->alpha, "Significance level of the Holm-corrected tests")
      ->check(CLI::Range(1e-6, 0.5))
      ->capture_default_str();
  return [o] { return run(*o); };
}

const CommandRegistration kStudyReportCommandRegistration{
    {"study-report", "A study's result: reward improvement per condition, Mann-Whitney U + Holm, plot, CSV/JSON/HTML",
     "skillcoach study-report --store ~/.local/share/skillcoach --study pilot --out pilot-report/",
     setup_study_report}};

}  // namespace
}  // namespace sc::cli
