#include "teaching/records/postgres_store.hpp"

#include <cstdio>
#include <optional>

#include "engine/core/error.hpp"
#include "teaching/records/data_dir.hpp"
#include "teaching/records/pg_handle.hpp"
#include "teaching/records/pg_schema_migrations.hpp"
#include "teaching/records/queued_record_store_impl.hpp"
#include "teaching/records/record_queries.hpp"
#include "teaching/records/record_studies.hpp"
#include "teaching/records/record_validation.hpp"
#include "teaching/records/record_writes.hpp"

namespace sc::records {
namespace {

constexpr int kConnectTimeoutSeconds = 3;

// FNV-1a of the redacted URL: one spill file per server and database, a stable short file name.
std::string spill_file_name(const std::string& label) {
  std::uint64_t hash = 1469598103934665603ull;
  for (unsigned char c : label) hash = (hash ^ c) * 1099511628211ull;
  char name[64];
  std::snprintf(name, sizeof name, "postgres-%016llx.pending.json", static_cast<unsigned long long>(hash));
  return name;
}

// Passing faults: the server is away, out of resources, shutting down, or a lock is busy. Anything else
// (a missing table, a refused row) needs someone to repair the database, so a retry is not promised.
bool is_passing_fault(const PgError& e) {
  if (e.connection_lost()) return true;
  for (const char* cls : {"40", "53", "55", "57", "58"})
    if (e.sqlstate().rfind(cls, 0) == 0) return true;
  return false;
}

}  // namespace

// A connection the server dropped (a restart) is only found out by using it: `fn` runs once more on a new
// connection. Only for work that is safe to repeat (reads, locks, BEGIN).
template <typename Fn>
auto PostgresStore::with_reconnect(Fn&& fn) const {
  try {
    return fn(connection());
  } catch (const PgError& e) {
    if (!e.connection_lost()) throw;
    db_.reset();
    return fn(connection());
  }
}

template <typename Fn>
auto PostgresStore::read(Fn&& query) const {
  try {
    return with_reconnect(query);
  } catch (const PgError& e) {
    throw InputError(label_.string(), std::string("cannot be read (") + e.what() + ")");
  }
}

template <typename Fn>
auto PostgresStore::write_now(const std::string& what, Fn&& write) {
  if (options_.read_only) throw InputError(label_.string(), "cannot " + what + ": the store was opened read-only");
  try {
    std::optional<PgTransaction> transaction;
    with_reconnect([&](PgDb& db) { return &transaction.emplace(db); });
    auto result = write(connection());
    transaction->commit();
    return result;
  } catch (const PgError& e) {
    throw InputError(label_.string(), "cannot " + what + ": " + e.what());
  }
}

PostgresStore::PostgresStore(std::string url, const std::filesystem::path& local_dir, StoreOptions options)
    : QueuedRecordStore(options), url_(std::move(url)), label_(redact_password(url_)) {
  const auto dir = local_dir.empty() ? default_data_dir() : local_dir;
  spill_ = dir / spill_file_name(label_.string());
  try {
    db_ = std::make_unique<PgDb>(url_, kConnectTimeoutSeconds);
    if (!options_.read_only) migrate_postgres(*db_, label_.string());
    if (pg_schema_version(*db_, label_.string()) != current_schema_version())
      throw InputError(label_.string(), "has no SkillCoach records of this schema version");
  } catch (const PgError& e) {
    throw InputError(label_.string(), std::string("cannot be opened (") + e.what() + ")");
  }
  if (options_.read_only) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  replay_spill_file();
}

PostgresStore::~PostgresStore() {
  try {
    if (!pending_.empty() && !options_.read_only) flush();  // on failure they are already in the spill file
    // Release the learners now: the server would drop the locks only once it notices the closed connection,
    // and a desktop reopening at once must not find its own learner still claimed.
    if (!claimed_.empty() && db_ && db_->connection_ok()) db_->exec("SELECT pg_advisory_unlock_all()");
  } catch (...) {  // a destructor must not throw
  }
}

PgDb& PostgresStore::connection() const {
  if (db_ && db_->connection_ok()) return *db_;
  db_.reset();  // the advisory locks went with the old connection
  auto db = std::make_unique<PgDb>(url_, kConnectTimeoutSeconds);
  for (const auto& name : claimed_) lock_learner(*db, name);
  db_ = std::move(db);
  return *db_;
}

void PostgresStore::lock_learner(PgDb& db, const std::string& name) const {
  auto lock = db.prepare("SELECT pg_try_advisory_lock(" + std::to_string(kSkillCoachApplicationId) + ", hashtext(?1))");
  lock.bind(1, name);
  const bool taken = lock.step() && lock.column_text(0) == "t";
  lock.run();
  if (!taken) {
    // 55P03 lock_not_available: a passing fault, the writes stay queued until the other desktop is done.
    throw PgError("55P03", false,
                  "learner \"" + name + "\" is already training on another desktop; finish or close it first");
  }
}

void PostgresStore::claim_learner(std::string_view name) const {
  if (options_.read_only || claimed_.count(name) != 0) return;
  try {
    with_reconnect([&](PgDb& db) {
      lock_learner(db, std::string(name));
      return 0;
    });
  } catch (const PgError& e) {
    throw InputError(label_.string(), e.what());
  }
  claimed_.emplace(name);
}

int PostgresStore::schema_version() const {
  return read([&](PgDb& db) { return pg_schema_version(db, label_.string()); });
}

std::string PostgresStore::retry_note() const {
  return retryable_ ? "will upload them when the server is back (next save)"
                    : "retrying cannot help until the server's database is repaired";
}

bool PostgresStore::try_write_pending(std::string& problem) {
  retryable_ = true;
  if (options_.read_only) {
    problem = "the store was opened read-only";
    return false;
  }
  for (int attempt = 1;; ++attempt) {
    try {
      while (!pending_.empty()) {
        PgDb& db = connection();
        PgTransaction transaction(db);
        apply_write(db, pending_.front());
        transaction.commit();
        pending_.pop_front();
      }
      return true;
    } catch (const PgError& e) {
      if (e.connection_lost()) db_.reset();
      // A connection the server dropped (a restart) fails once; a fresh one may work at once.
      if (e.connection_lost() && attempt == 1) continue;
      problem = e.connection_lost() ? std::string("the server cannot be reached: ") + e.what() : e.what();
      retryable_ = is_passing_fault(e);
    } catch (const InputError& e) {
      problem = e.what();
    }
    return false;
  }
}

StudyParticipant PostgresStore::enrol(std::string_view study, std::string_view learner, std::string_view enrolled) {
  require_learner_name(learner);
  require_text(enrolled, "enrolment time");
  // Serialised per study: two desktops enrolling at once would both read the same count of places taken.
  return write_now("enrol \"" + std::string(learner) + "\"", [&](PgDb& db) {
    db.prepare("SELECT pg_advisory_xact_lock(hashtext(?1))").bind(1, "study:" + std::string(study)).run();
    return enrol_participant(db, study, learner, enrolled);
  });
}

template class QueuedRecordStore<PostgresStore, PgDb, PgError>;

}  // namespace sc::records
