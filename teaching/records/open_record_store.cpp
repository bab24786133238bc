#include "teaching/records/open_record_store.hpp"

#include "teaching/records/data_dir.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/records/postgres_store.hpp"

namespace sc::records {

bool is_server_store(std::string_view store) {
  return store.rfind("postgresql://", 0) == 0 || store.rfind("postgres://", 0) == 0;
}

std::unique_ptr<RecordStore> open_record_store(const std::string& store, StoreOptions options,
                                               const std::filesystem::path& local_dir) {
  if (is_server_store(store)) return std::make_unique<PostgresStore>(store, local_dir, options);
  return std::make_unique<LearnerStore>(data_dir_of_store(store), options);
}

}  // namespace sc::records
