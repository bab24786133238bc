#pragma once
// PostgresStore: the RecordStore (record_store.hpp) on a PostgreSQL server, so a class of desktops or the
// sites of a study keep one pool of records. Same schema versions (pg_schema_migrations.hpp) and the same
// record SQL as the SQLite store.
//
//  - Each record is one transaction, a trial with its resume point.
//  - When the server cannot be reached (or fails for a passing reason), the write is queued in memory and
//    in a spill file in the desktop's local data directory ("postgres-<hash of the URL>.pending.json"),
//    SaveResult says so, and the queue is uploaded in order on the next write, flush(), or the next store
//    opened on that server from that data directory. Replays are idempotent (record_writes.hpp).
//  - One desktop per learner: a writable store holds a session-level advisory lock per claimed learner
//    (key: the SkillCoach application id and hashtext(name)) on its connection; a second desktop is
//    refused. After a lost connection the locks are taken again before any queued write is uploaded; if
//    another desktop took the learner meanwhile, the writes stay queued instead of being merged.
// Not thread-safe: one store per thread.
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "teaching/records/queued_record_store.hpp"
#include "teaching/records/record_store.hpp"

namespace sc::records {

class PgDb;
class PgError;

class PostgresStore final : public QueuedRecordStore<PostgresStore, PgDb, PgError> {
 public:
  // `url`: postgresql://[user[:password]@][host][:port]/database[?...]. `local_dir` keeps the spill file
  // (empty: default_data_dir()). Throws sc::InputError when the server cannot be reached or refuses us,
  // or holds a newer or foreign schema.
  PostgresStore(std::string url, const std::filesystem::path& local_dir, StoreOptions options = {});
  ~PostgresStore() override;  // tries a last upload; whatever is still pending stays in the spill file
  PostgresStore(const PostgresStore&) = delete;
  PostgresStore& operator=(const PostgresStore&) = delete;

  const std::filesystem::path& database_path() const override { return label_; }
  std::filesystem::path spill_path() const override { return spill_; }
  int schema_version() const override;
  bool writable() const override { return !options_.read_only; }
  void claim_learner(std::string_view name) const override;
  StudyParticipant enrol(std::string_view study, std::string_view learner, std::string_view enrolled) override;

 private:
  friend class QueuedRecordStore<PostgresStore, PgDb, PgError>;
  PgDb& connection() const;
  void lock_learner(PgDb& db, const std::string& name) const;
  bool try_write_pending(std::string& problem);
  std::string unsaved_words() const { return "not saved on the server yet"; }
  std::string retry_note() const;
  template <typename Fn>
  auto with_reconnect(Fn&& fn) const;
  template <typename Fn>
  auto read(Fn&& query) const;  // one retry on a fresh connection; failures become sc::InputError
  template <typename Fn>
  auto write_now(const std::string& what, Fn&& write);  // one transaction; failures throw sc::InputError

  std::string url_;
  std::filesystem::path label_;  // the URL without its password
  std::filesystem::path spill_;
  mutable std::unique_ptr<PgDb> db_;  // null or broken after a lost connection; connection() reconnects
  mutable std::set<std::string, std::less<>> claimed_;
};

extern template class QueuedRecordStore<PostgresStore, PgDb, PgError>;

}  // namespace sc::records
