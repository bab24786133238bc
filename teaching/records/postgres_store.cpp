#include "teaching/records/postgres_store.hpp"

#include <cstdio>
#include <optional>

#include "engine/core/error.hpp"
#include "teaching/records/data_dir.hpp"
#include "teaching/records/pg_handle.hpp"
#include "teaching/records/pg_schema_migrations.hpp"
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
    : url_(std::move(url)), label_(redact_password(url_)), options_(options) {
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
  load_spill_file();
  if (!pending_.empty()) {
    const auto result = flush();
    if (!result.message.empty()) open_message_ += (open_message_.empty() ? "" : "; ") + result.message;
  }
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

void PostgresStore::load_spill_file() {
  std::error_code ec;
  if (!std::filesystem::exists(spill_, ec)) return;
  try {
    for (auto& write : read_spill_file(spill_)) pending_.push_back(std::move(write));
  } catch (const InputError& e) {
    auto aside = spill_;  // never overwrite what may be a learner's only copy of a trial
    aside += ".unreadable";
    std::filesystem::rename(spill_, aside, ec);
    open_message_ = std::string(e.what()) + (ec ? "; left in place" : "; moved to " + aside.string());
  }
}

std::int64_t PostgresStore::ensure_learner(std::string_view name, std::string_view created) {
  require_learner_name(name);
  require_text(created, "learner creation time");
  return write_now("save learner \"" + std::string(name) + "\"",
                   [&](PgDb& db) { return insert_learner_if_new(db, name, created); });
}

std::int64_t PostgresStore::begin_session(const NewSession& session) {
  validate_new_session(session);
  claim_learner(session.learner);
  const auto id = write_now("start a session for \"" + session.learner + "\"", [&](PgDb& db) {
    const auto session_id = insert_session(db, insert_learner_if_new(db, session.learner, session.started), session);
    if (!session.study.empty()) attach_session_to_study(db, session_id, session);
    return session_id;
  });
  last_seq_[id] = 0;
  return id;
}

SaveResult PostgresStore::record_trial(const TrialRecord& trial) {
  require_session(trial.session_id);
  validate_trial(trial);
  return submit(TrialWrite{trial, next_seq(trial.session_id)});
}

SaveResult PostgresStore::save_diagnosis(const DiagnosisRecord& diagnosis) {
  require_session(diagnosis.session_id);
  validate_diagnosis(diagnosis);
  return submit(diagnosis);
}

SaveResult PostgresStore::save_curriculum(const CurriculumRecord& curriculum) {
  require_session(curriculum.session_id);
  validate_curriculum(curriculum);
  return submit(curriculum);
}

SaveResult PostgresStore::save_progress(std::int64_t session_id, const SessionProgress& progress) {
  require_session(session_id);
  validate_progress(progress);
  return submit(ProgressWrite{session_id, progress});
}

SaveResult PostgresStore::finish_session(std::int64_t session_id, std::string_view finished) {
  require_session(session_id);
  require_text(finished, "session end time");
  return submit(FinishWrite{session_id, std::string(finished)});
}

SaveResult PostgresStore::submit(PendingWrite write) {
  pending_.push_back(std::move(write));
  return flush();  // the new write is last in the queue, so it is stored iff the queue empties
}

SaveResult PostgresStore::flush() {
  if (pending_.empty()) return {true, 0, {}};
  std::string problem;
  if (try_write_pending(problem)) {
    std::error_code ec;
    std::filesystem::remove(spill_, ec);  // everything it held is on the server now
    return {true, 0, {}};
  }
  const auto count = pending_.size();
  const std::string next = retryable_ ? "will upload them when the server is back (next save)"
                                      : "retrying cannot help until the server's database is repaired";
  return {false, count,
          label_.string() + ": " + std::to_string(count) + (count == 1 ? " record" : " records") +
              " not saved on the server yet (" + problem + "); " + spill_pending() + "; " + next};
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

std::string PostgresStore::spill_pending() {
  spilled_ = false;
  if (options_.read_only) return "kept in memory only (store opened read-only)";
  try {
    write_spill_file(spill_, label_, pending_);
    spilled_ = true;
    return "kept in memory and in " + spill_.string();
  } catch (const InputError& e) {
    return std::string("kept in memory only (") + e.what() + ")";
  }
}

int PostgresStore::next_seq(std::int64_t session_id) {
  auto it = last_seq_.find(session_id);
  if (it == last_seq_.end()) {
    int last = 0;
    try {
      last = query_last_seq(connection(), session_id);
    } catch (const PgError&) {  // unreachable now: the pending queue below still orders this session
    }
    it = last_seq_.emplace(session_id, last_seq_with_pending(pending_, session_id, last)).first;
  }
  return ++it->second;
}

void PostgresStore::require_session(std::int64_t session_id) const {
  if (last_seq_.count(session_id) != 0) return;
  bool known = true;
  try {
    known = query_session(connection(), session_id).has_value();
  } catch (const PgError&) {  // cannot check now; a write for an unknown session would stay pending
  }
  if (!known) throw InputError(label_.string(), "unknown session id " + std::to_string(session_id));
}

std::optional<ResumePoint> PostgresStore::find_unfinished_session(std::string_view learner,
                                                                  std::string_view task) const {
  claim_learner(learner);
  const auto sessions = read([&](PgDb& db) { return query_unfinished_sessions(db, learner, task); });
  for (const auto& row : sessions) {
    ResumePoint point{row, read([&](PgDb& db) { return query_trial_count(db, row.id); })};
    if (!apply_pending_to_resume(point, pending_)) return point;  // pending writes are the learner's work too
  }
  return std::nullopt;
}

int PostgresStore::session_count(std::string_view learner, std::string_view task) const {
  return read([&](PgDb& db) { return query_session_count(db, learner, task); });
}

std::optional<SessionRow> PostgresStore::session(std::int64_t session_id) const {
  return read([&](PgDb& db) { return query_session(db, session_id); });
}

std::vector<LearnerOverview> PostgresStore::list_learners() const {
  return read([](PgDb& db) { return query_learners(db); });
}

std::vector<StoredTrial> PostgresStore::trials_of_session(std::int64_t session_id) const {
  return read([&](PgDb& db) { return query_trials(db, session_id); });
}

std::vector<DiagnosisRecord> PostgresStore::diagnoses_of_session(std::int64_t session_id) const {
  return read([&](PgDb& db) { return query_diagnoses(db, session_id); });
}

std::vector<CurriculumRecord> PostgresStore::curricula_of_session(std::int64_t session_id) const {
  return read([&](PgDb& db) { return query_curricula(db, session_id); });
}

void PostgresStore::create_study(const StudyDefinition& study) {
  validate_study(study);
  write_now("create study \"" + study.name + "\"", [&](PgDb& db) {
    insert_study(db, study);
    return 0;
  });
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

std::optional<StudyDefinition> PostgresStore::study(std::string_view name) const {
  return read([&](PgDb& db) { return query_study(db, name); });
}

std::vector<StudyDefinition> PostgresStore::list_studies() const {
  return read([](PgDb& db) { return query_studies(db); });
}

std::vector<StudyParticipant> PostgresStore::study_participants(std::string_view study) const {
  return read([&](PgDb& db) { return query_participants(db, study); });
}

std::vector<SessionSummary> PostgresStore::study_sessions(std::string_view study) const {
  return read([&](PgDb& db) { return query_study_sessions(db, study); });
}

}  // namespace sc::records
