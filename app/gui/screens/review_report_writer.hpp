#pragma once
// `skillcoach report`'s work: reads a learner's sessions from the database (read-only), reviews every trial,
// renders the pictures offscreen and writes them with trials.csv, trials.json and report.html into `out`.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sc {

struct ReportRequest {
  std::filesystem::path data_dir;
  std::string store;  // non-empty: read this store instead (e.g. a class's postgresql:// URL)
  std::string learner;
  std::optional<std::int64_t> session;  // none: every session of the learner
  // Sessions started within [from, to]: ISO-8601 prefixes ("2026-12-01", "2026-12-01T14"), compared as text
  // (stored start times are ISO-8601 UTC); empty: no bound.
  std::string from;
  std::string to;
  std::filesystem::path out;
  int image_width = 1280;
  int image_height = 720;
};

struct ReportResult {
  std::vector<std::filesystem::path> files;  // every file written, report.html last
  int sessions = 0;
  int trials = 0;
  // Damaged rows left out of the report, one line each ("<db>: session 1, trial 2 left out: ..."); the rest
  // is written. The command exits non-zero when there are any.
  std::vector<std::string> problems;
};

// Throws InputError (one line naming the file) for a missing/damaged database, an unknown learner or
// session, a task without data, or an output that cannot be written. Never writes the database.
ReportResult write_learner_report(const ReportRequest& request);

}  // namespace sc
