#pragma once
// LearnerStore: the SQLite RecordStore (record_store.hpp): everything a learner does, kept in one SQLite file
// (docs/database.md documents the schema). The trainer writes through it as a session goes; the instructor review and
// the export read it back.
//
// Safety rules:
//  - WAL journal, synchronous=FULL, foreign keys on; each record is committed in its own transaction the
//    moment it is handed over, and a trial is committed together with its resume point.
//  - A damaged, foreign or newer-schema file is refused with a one-line sc::InputError and never written.
//  - A write that fails for a storage reason (disk full, read-only, locked, I/O error) does not throw: the
//    record stays in an in-memory queue, is spilled to "<db>.pending.json" (atomically), and is retried on
//    the next write or flush(). The next store opened on the database replays a spill file it finds.
// Not thread-safe: one store per thread (SQLite itself handles other processes).
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "teaching/records/data_dir.hpp"
#include "teaching/records/learner_lock.hpp"
#include "teaching/records/queued_record_store.hpp"
#include "teaching/records/record_store.hpp"
#include "teaching/records/record_types.hpp"
#include "teaching/records/study_records.hpp"

namespace sc::records {

class SqliteDb;
class SqliteError;

class LearnerStore final : public QueuedRecordStore<LearnerStore, SqliteDb, SqliteError> {
 public:
  static constexpr std::string_view kDatabaseFileName = "skillcoach.db";

  // Opens (or creates) `data_dir`/skillcoach.db; an empty `data_dir` means default_data_dir().
  // Throws sc::InputError for a damaged/foreign/newer database, or when it cannot be opened at all.
  explicit LearnerStore(const std::filesystem::path& data_dir, StoreOptions options = {});
  ~LearnerStore() override;  // tries a last flush; whatever is still pending stays in the spill file
  LearnerStore(const LearnerStore&) = delete;
  LearnerStore& operator=(const LearnerStore&) = delete;

  const std::filesystem::path& database_path() const override { return path_; }
  std::filesystem::path spill_path() const override;
  int schema_version() const override;
  // False while the database cannot be written (opened read-only, or the file/directory is read-only).
  bool writable() const override;
  // One trainer per learner on this desktop (learner_lock.hpp).
  void claim_learner(std::string_view name) const override;
  StudyParticipant enrol(std::string_view study, std::string_view learner, std::string_view enrolled) override;

 private:
  friend class QueuedRecordStore<LearnerStore, SqliteDb, SqliteError>;
  std::unique_ptr<SqliteDb> connect() const;
  std::unique_ptr<SqliteDb> connect_immutable() const;
  SqliteDb& connection() const;
  void reconnect();
  std::unique_ptr<SqliteDb> readable_schema(std::unique_ptr<SqliteDb> db) const;
  bool try_write_pending(std::string& problem);
  std::string unsaved_words() const { return "not saved yet"; }
  std::string retry_note() const;
  template <typename Fn>
  auto read(Fn&& query) const;  // runs a query; SQLite failures become sc::InputError
  template <typename Fn>
  auto write_now(const std::string& what, Fn&& write);  // one transaction; failures throw sc::InputError

  std::filesystem::path path_;
  mutable std::unique_ptr<SqliteDb> db_;  // null only after a failed reconnect; connection() retries
  std::unique_ptr<LearnerLocks> locks_;   // mutable through the pointer: claims are not database content
};

extern template class QueuedRecordStore<LearnerStore, SqliteDb, SqliteError>;

}  // namespace sc::records
