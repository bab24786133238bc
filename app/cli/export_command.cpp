// skillcoach export: the whole learner database as one JSON document (trials embed their trajectory
// files). Reads the database read-only; a missing, damaged, foreign or newer database exits with 2, and so
// does an export that had to leave damaged rows out (one line each).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/records/records_export.hpp"

namespace sc::cli {
namespace {

struct ExportOptions {
  std::string data_dir;
  std::string store;  // instead of data_dir: any store (e.g. a postgresql:// URL)
  std::string out;
};

CommandRunner setup_export(CLI::App& sub) {
  auto options = std::make_shared<ExportOptions>();
  sub.add_option("--data-dir", options->data_dir,
                 "Directory holding skillcoach.db (default: $XDG_DATA_HOME/skillcoach or ~/.local/share/skillcoach)");
  sub.add_option("--store", options->store, "Instead of --data-dir: a data directory or a postgresql:// URL")
      ->excludes("--data-dir");
  sub.add_option("--out", options->out, "JSON file to write")->required();
  return [options] {
    const std::filesystem::path data_dir =
        options->data_dir.empty() ? records::default_data_dir() : std::filesystem::path(options->data_dir);
    std::string from = (data_dir / records::LearnerStore::kDatabaseFileName).string();
    records::RecordsExport result;
    if (options->store.empty()) {
      result = records::export_database(data_dir, options->out);
    } else {
      const auto store = records::open_record_store(options->store, records::StoreOptions{.read_only = true});
      from = store->database_path().string();
      result = records::export_store(*store, options->out);
    }
    std::printf("exported %zu trials from %s to %s\n", result.trials, from.c_str(), options->out.c_str());
    // Damaged rows: the rest is exported, but the command must not report a complete export.
    for (const auto& problem : result.problems) std::fprintf(stderr, "skillcoach: error: %s\n", problem.c_str());
    return result.problems.empty() ? 0 : 2;
  };
}

const CommandRegistration kExportCommandRegistration{
    {"export", "Export every learner record (trials with their trajectories) as JSON",
     "skillcoach export --data-dir ~/.local/share/skillcoach --out records.json", setup_export}};

}  // namespace
}  // namespace sc::cli
