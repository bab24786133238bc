// skillcoach import: writes the records of a `skillcoach export` file into a store (a data directory or a
// postgresql:// URL), so a desktop's records join a class's server or a server's records go to a laptop.
// Refuses a store that already holds one of the file's learners or studies; exit 2 on any refusal.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/records/records_import.hpp"

namespace sc::cli {
namespace {

struct ImportOptions {
  std::string store;
  std::string in;
};

CommandRunner setup_import(CLI::App& sub) {
  auto options = std::make_shared<ImportOptions>();
  sub.add_option("--store", options->store,
                 "Destination: data directory, its skillcoach.db, or a postgresql:// URL (default: "
                 "$XDG_DATA_HOME/skillcoach or ~/.local/share/skillcoach)");
  sub.add_option("--in", options->in, "JSON file written by `skillcoach export`")->required();
  return [options] {
    const Json doc = read_json_file(options->in);
    const auto store = records::open_record_store(options->store);
    const auto result = records::import_records(doc, options->in, *store);
    std::printf("imported %zu learners, %zu studies, %zu sessions and %zu trials from %s into %s", result.learners,
                result.studies, result.sessions, result.trials, options->in.c_str(),
                store->database_path().string().c_str());
    if (result.sessions_already_there > 0)
      std::printf(" (%zu sessions were there already: skipped)", result.sessions_already_there);
    std::printf("\n");
    return 0;
  };
}

const CommandRegistration kImportCommandRegistration{
    {"import", "Import the records of an export file into a store (SQLite or PostgreSQL)",
     "skillcoach import --in records.json --store postgresql://coach@server/skillcoach", setup_import}};

}  // namespace
}  // namespace sc::cli
