#include "teaching/records/learner_store.hpp"

#include <sqlite3.h>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/records/database_file_check.hpp"
#include "teaching/records/queued_record_store_impl.hpp"
#include "teaching/records/record_queries.hpp"
#include "teaching/records/record_studies.hpp"
#include "teaching/records/record_validation.hpp"
#include "teaching/records/record_writes.hpp"
#include "teaching/records/schema_migrations.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {

template <typename Fn>
auto LearnerStore::read(Fn&& query) const {
  try {
    return query(connection());
  } catch (const SqliteError& e) {
    throw InputError(path_.string(), "cannot be read (" + describe_storage_error(e) + ")");
  }
}

template <typename Fn>
auto LearnerStore::write_now(const std::string& what, Fn&& write) {
  if (options_.read_only) throw InputError(path_.string(), "cannot " + what + ": the database was opened read-only");
  try {
    if (connection().is_read_only()) reconnect();
    SqliteTransaction transaction(connection());
    auto result = write(connection());
    transaction.commit();
    return result;
  } catch (const SqliteError& e) {
    throw InputError(path_.string(), "cannot " + what + ": " + describe_storage_error(e));
  }
}

LearnerStore::LearnerStore(const std::filesystem::path& data_dir, StoreOptions options) : QueuedRecordStore(options) {
  const auto dir = data_dir.empty() ? default_data_dir() : data_dir;
  path_ = dir / kDatabaseFileName;
  locks_ = std::make_unique<LearnerLocks>(path_.string() + ".lock");
  if (options_.read_only) {
    std::error_code ec;  // the non-throwing forms here and below: EACCES is a one-line problem
    if (!std::filesystem::exists(path_, ec) && !ec) throw InputError(path_.string(), "no such database");
  } else {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::error_code is_dir_error;
    if (ec && !std::filesystem::is_directory(dir, is_dir_error))
      throw InputError(dir.string(), "cannot create the data directory: " + ec.message());
  }
  const auto state = check_database_file(path_, current_schema_version());
  if (state.is_new && options_.read_only) throw InputError(path_.string(), "is empty (no SkillCoach records)");
  db_ = connect();
  if (!options_.read_only) replay_spill_file();
}

LearnerStore::~LearnerStore() {
  if (pending_.empty() || options_.read_only) return;
  try {
    flush();       // on failure the pending writes are already in the spill file
  } catch (...) {  // a destructor must not throw; nothing more can be done here
  }
}

std::filesystem::path LearnerStore::spill_path() const {
  auto spill = path_;
  spill += ".pending.json";
  return spill;
}

int LearnerStore::schema_version() const {
  return read([](SqliteDb& db) { return static_cast<int>(db.query_int("PRAGMA user_version")); });
}

bool LearnerStore::writable() const { return !options_.read_only && !connection().is_read_only(); }

SqliteDb& LearnerStore::connection() const {
  if (!db_) db_ = connect();  // a previous reconnect failed; this throws sc::InputError if it fails again
  return *db_;
}

void LearnerStore::reconnect() {
  // Close first: connections of one process share SQLite's WAL index, so a new connection would inherit
  // the old one's read-only mapping.
  db_.reset();
  db_ = connect();
}

std::unique_ptr<SqliteDb> LearnerStore::connect() const {
  const std::string where = path_.string();
  std::error_code ec;
  if (std::filesystem::exists(path_, ec) && read_immutably(path_)) return connect_immutable();
  try {
    auto db = std::make_unique<SqliteDb>(
        path_, options_.read_only ? SqliteDb::Mode::ReadOnly : SqliteDb::Mode::ReadWriteCreate);
    db->set_busy_timeout(options_.busy_timeout_ms);
    db->exec("PRAGMA foreign_keys = ON");
    if (db->is_read_only()) return readable_schema(std::move(db));
    // WAL: readers never block the trainer's writes, and a commit is one append to the log.
    // synchronous=FULL: the log is fsynced at every commit, so a finished trial survives a power cut too,
    // not only a crash of the program (NORMAL would only guarantee the latter). A commit per trial
    // (one every few seconds at most) makes the fsync cost irrelevant; see app/bench/records_bench.cpp.
    const auto mode = db->query_text("PRAGMA journal_mode = WAL");
    if (mode != "wal") throw InputError(where, "cannot use write-ahead logging (journal mode stays " + mode + ")");
    db->exec("PRAGMA synchronous = FULL");
    if (options_.max_page_count > 0)
      db->query_int("PRAGMA max_page_count = " + std::to_string(options_.max_page_count));
    migrate(*db, schema_migrations(), where);
    return db;
  } catch (const SqliteError& e) {
    const int code = e.primary_code();
    if (options_.read_only || (code != SQLITE_READONLY && code != SQLITE_CANTOPEN && code != SQLITE_PERM))
      throw InputError(where, "cannot be opened (" + describe_storage_error(e) + ")");
  }
  return connect_immutable();
}

// The file or its directory is read-only to us: read through an immutable connection, which creates no
// files (see read_immutably), and queue every write until the database is writable again.
std::unique_ptr<SqliteDb> LearnerStore::connect_immutable() const {
  try {
    auto db = std::make_unique<SqliteDb>(path_, SqliteDb::Mode::ReadOnly, "immutable=1");
    db->exec("PRAGMA foreign_keys = ON");
    return readable_schema(std::move(db));
  } catch (const SqliteError& e) {
    throw InputError(path_.string(), "cannot be opened (" + describe_storage_error(e) + ")");
  }
}

// A read-only store (export, report, review) reads an older database through a migrated copy in memory, so
// the file is never changed; a writable store on a read-only file cannot upgrade it and says so.
std::unique_ptr<SqliteDb> LearnerStore::readable_schema(std::unique_ptr<SqliteDb> db) const {
  const auto version = db->query_int("PRAGMA user_version");
  if (version < current_schema_version() && options_.read_only)
    return migrated_in_memory(*db, schema_migrations(), path_.string());
  if (version != current_schema_version()) {
    throw InputError(path_.string(), "has schema version " + std::to_string(version) + " and needs upgrading to " +
                                         std::to_string(current_schema_version()) + ", but it is read-only");
  }
  return db;
}

std::string LearnerStore::retry_note() const {
  return retryable_ ? "will retry on the next save"
                    : "retrying cannot help until the database is repaired or moved aside";
}

bool LearnerStore::try_write_pending(std::string& problem) {
  retryable_ = true;
  if (options_.read_only) {
    problem = "the database was opened read-only";
    return false;
  }
  try {
    if (connection().is_read_only()) reconnect();  // the file or directory may have become writable
    if (connection().is_read_only()) {
      problem = "the database file or its directory is read-only";
      return false;
    }
    while (!pending_.empty()) {
      SqliteTransaction transaction(connection());
      apply_write(connection(), pending_.front());
      transaction.commit();
      pending_.pop_front();
    }
    return true;
  } catch (const SqliteError& e) {
    problem = describe_storage_error(e);
    retryable_ = is_storage_fault(e);
  } catch (const InputError& e) {
    problem = e.what();
  }
  return false;
}

void LearnerStore::claim_learner(std::string_view name) const {
  if (!options_.read_only) locks_->claim(name);
}

StudyParticipant LearnerStore::enrol(std::string_view study, std::string_view learner, std::string_view enrolled) {
  require_learner_name(learner);
  require_text(enrolled, "enrolment time");
  return write_now("enrol \"" + std::string(learner) + "\"",
                   [&](SqliteDb& db) { return enrol_participant(db, study, learner, enrolled); });
}

template class QueuedRecordStore<LearnerStore, SqliteDb, SqliteError>;

}  // namespace sc::records
