#pragma once
// Which RecordStore a `--store` value names: a postgresql:// (or postgres://) URL opens a PostgresStore,
// anything else a data directory (or its skillcoach.db) with the SQLite LearnerStore; empty means the
// default data directory.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "teaching/records/record_store.hpp"

namespace sc::records {

bool is_server_store(std::string_view store);

// `local_dir` keeps a server store's spill file (empty: default_data_dir()). Throws sc::InputError as
// the stores' constructors do, and for a URL of another kind.
std::unique_ptr<RecordStore> open_record_store(const std::string& store, StoreOptions options = {},
                                               const std::filesystem::path& local_dir = {});

}  // namespace sc::records
