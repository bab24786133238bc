#pragma once
// The whole learner database as one JSON document (`skillcoach export`): learners, their sessions with
// the review summary, every trial with its trajectory-file document embedded as JSON, diagnoses by round
// and curricula with their drills. Deterministic: same database, same bytes.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/records/learner_store.hpp"

namespace sc::records {

inline constexpr std::string_view kExportFormat = "skillcoach-records";
inline constexpr int kExportVersion = 1;

struct RecordsExport {
  Json doc;
  std::size_t trials = 0;             // trials in `doc`
  std::vector<std::string> problems;  // one line per damaged row left out, naming the database and the row
};

// Every readable record; rows whose stored JSON is damaged are left out and listed in `problems`.
RecordsExport export_records(const RecordStore& store);

// Opens `data_dir` read-only and writes the export to `out` atomically; throws sc::InputError (missing,
// damaged, foreign or newer database; unwritable output).
RecordsExport export_database(const std::filesystem::path& data_dir, const std::filesystem::path& out);
// The same from any opened store (a PostgreSQL one included).
RecordsExport export_store(const RecordStore& store, const std::filesystem::path& out);

}  // namespace sc::records
