#pragma once
// RecordStore: what the trainer, the instructor review, the export and the study commands need from the
// place learner records are kept. Two implementations share the schema (schema_migrations.hpp) and the
// record SQL: LearnerStore, one SQLite file on the desktop (the default), and PostgresStore, a PostgreSQL
// server that a whole class or a multi-site study shares. open_record_store.hpp picks one from a
// `--store` value. docs/database.md describes both.
//
// The contract every implementation keeps:
//  - each record is committed in its own transaction the moment it is handed over, a trial together with
//    its resume point;
//  - a write that fails for a storage reason (disk full, server unreachable, ...) does not throw: the
//    record stays queued in memory and in a local spill file (pending_writes.hpp), is retried on the next
//    write or flush(), and SaveResult tells the learner;
//  - one trainer per learner: a writable store claims the learner and holds the claim until it is
//    destroyed; a second trainer is refused, never merged.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "teaching/records/record_types.hpp"
#include "teaching/records/study_records.hpp"

namespace sc::records {

struct StoreOptions {
  bool read_only = false;           // review/export: never writes (writes stay pending, nothing is spilled)
  int busy_timeout_ms = 2000;       // how long a write waits for another writer's lock before it is queued
  std::int64_t max_page_count = 0;  // SQLite only. 0: unlimited; otherwise the database acts as a full disk
};

class RecordStore {
 public:
  virtual ~RecordStore() = default;

  // Where the records are, for messages: the SQLite file, or the server's URL without its password.
  virtual const std::filesystem::path& database_path() const = 0;
  // The local file that keeps writes the store could not make yet.
  virtual std::filesystem::path spill_path() const = 0;
  virtual int schema_version() const = 0;
  virtual bool writable() const = 0;

  // ---- the trainer's writes ----
  // Learners and sessions are created before any work exists, so a failure throws sc::InputError
  // (the app shows it and can retry) instead of being queued.
  virtual std::int64_t ensure_learner(std::string_view name, std::string_view created) = 0;
  virtual std::int64_t begin_session(const NewSession& session) = 0;
  // One trainer per learner: a writable store claims the learner in begin_session and
  // find_unfinished_session, and holds the claim until it is destroyed. Throws sc::InputError when another
  // trainer holds them.
  virtual void claim_learner(std::string_view name) const = 0;
  // These never throw for storage faults (see SaveResult); they throw sc::InputError for an invalid
  // record (unknown session, payload that is not JSON, empty task/device/timestamps, non-finite score).
  virtual SaveResult record_trial(const TrialRecord& trial) = 0;  // assigns the next seq of the session
  virtual SaveResult save_diagnosis(const DiagnosisRecord& diagnosis) = 0;
  virtual SaveResult save_curriculum(const CurriculumRecord& curriculum) = 0;
  virtual SaveResult save_progress(std::int64_t session_id, const SessionProgress& progress) = 0;
  virtual SaveResult finish_session(std::int64_t session_id, std::string_view finished) = 0;
  // Retries the pending writes (reconnecting or reopening the database if it must).
  virtual SaveResult flush() = 0;
  virtual std::size_t pending_count() const = 0;
  // True when every pending write is also in the spill file, so it survives the end of the program.
  virtual bool pending_spilled() const = 0;
  // Non-empty when opening found something the user should know (e.g. an unreadable spill file).
  virtual const std::string& open_message() const = 0;

  // ---- resuming ----
  // The newest unfinished session of `learner` for `task` (any task if empty), with pending writes applied.
  // A writable store claims the learner first (claim_learner), so two trainers never resume one session.
  virtual std::optional<ResumePoint> find_unfinished_session(std::string_view learner,
                                                             std::string_view task = {}) const = 0;
  // How many sessions of `task` the learner has begun (sessions are never pending: begin_session stores or
  // throws).
  virtual int session_count(std::string_view learner, std::string_view task) const = 0;

  // ---- instructor review (stored content only) ----
  virtual std::optional<SessionRow> session(std::int64_t session_id) const = 0;
  virtual std::vector<LearnerOverview> list_learners() const = 0;
  virtual std::vector<StoredTrial> trials_of_session(std::int64_t session_id) const = 0;         // in seq order
  virtual std::vector<DiagnosisRecord> diagnoses_of_session(std::int64_t session_id) const = 0;  // by round
  // By round, drills by index.
  virtual std::vector<CurriculumRecord> curricula_of_session(std::int64_t session_id) const = 0;

  // ---- studies (study_records.hpp) ----
  // Like learners and sessions, these throw sc::InputError instead of queueing: a study and an enrolment
  // exist before any work. create_study refuses an invalid definition or a name in use.
  virtual void create_study(const StudyDefinition& study) = 0;
  // Enrols `learner` with the next condition of the study's randomisation (an enrolled learner keeps their
  // place and condition); a full or unknown study is refused. One transaction: concurrent enrolments never
  // share a place.
  virtual StudyParticipant enrol(std::string_view study, std::string_view learner, std::string_view enrolled) = 0;
  virtual std::optional<StudyDefinition> study(std::string_view name) const = 0;
  virtual std::vector<StudyDefinition> list_studies() const = 0;
  virtual std::vector<StudyParticipant> study_participants(std::string_view study) const = 0;  // enrolment order
  virtual std::vector<SessionSummary> study_sessions(std::string_view study) const = 0;        // oldest first
};

}  // namespace sc::records
