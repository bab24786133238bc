// skillcoach report: an instructor's report of one learner (all sessions, or one) from the learner database,
// opened read-only: every trial's picture, before/after overlays, the expertise chart, trials.csv,
// trials.json and a self-contained report.html. The work is in app/gui/screens/review_report_writer.cpp.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/gui/screens/review_report_writer.hpp"
#include "teaching/records/data_dir.hpp"
#include "teaching/review/session_filter.hpp"

namespace sc::cli {
namespace {

struct ReportOptions {
  std::string data_dir;
  std::string store;
  std::string from;
  std::string to;
  std::string learner;
  std::int64_t session = 0;
  std::string out;
};

CommandRunner setup_report(CLI::App& sub) {
  auto options = std::make_shared<ReportOptions>();
  sub.add_option("--data-dir", options->data_dir,
                 "Directory holding skillcoach.db (default: $XDG_DATA_HOME/skillcoach or ~/.local/share/skillcoach)");
  sub.add_option("--store", options->store, "Instead of --data-dir: a data directory or a class's postgresql:// URL")
      ->excludes("--data-dir");
  sub.add_option("--learner", options->learner, "Learner's name")->required();
  const auto iso_date = [](const std::string& v) {
    return review::valid_date_bound(v) ? std::string() : "not an ISO date (YYYY-MM-DD, or YYYY-MM-DDTHH:MM)";
  };
  sub.add_option("--from", options->from, "Only sessions started on or after this ISO date/time (e.g. 2026-12-01)")
      ->check(iso_date);
  sub.add_option("--to", options->to, "Only sessions started on or before this ISO date/time (e.g. 2026-12-03)")
      ->check(iso_date);
  CLI::Option* session =
      sub.add_option("--session", options->session, "Only this session id (default: every session of the learner)");
  sub.add_option("--out", options->out, "Folder to write the report into (created)")->required();
  return [options, session] {
    ReportRequest request;
    request.data_dir =
        options->data_dir.empty() ? records::default_data_dir() : std::filesystem::path(options->data_dir);
    request.store = options->store;
    request.learner = options->learner;
    request.from = options->from;
    request.to = options->to;
    if (session->count() > 0) request.session = options->session;
    request.out = options->out;
    const ReportResult result = write_learner_report(request);
    std::printf("report of %s: %d session(s), %d trials, %zu files in %s\n", options->learner.c_str(), result.sessions,
                result.trials, result.files.size(), options->out.c_str());
    for (const std::string& problem : result.problems) std::fprintf(stderr, "skillcoach: error: %s\n", problem.c_str());
    return result.problems.empty() ? 0 : 2;
  };
}

const CommandRegistration kReportCommandRegistration{
    {"report", "Write an instructor's report of a learner (pictures, CSV/JSON, HTML)",
     "skillcoach report --data-dir DIR --learner Ada --out report/", setup_report}};

}  // namespace
}  // namespace sc::cli
