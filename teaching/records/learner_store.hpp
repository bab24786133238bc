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
#include "teaching/records/pending_writes.hpp"
#include "teaching/records/record_store.hpp"
#include "teaching/records/record_types.hpp"
#include "teaching/records/study_records.hpp"

namespace sc::records {

class SqliteDb;

class LearnerStore final : public RecordStore {
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

  // ---- the trainer's writes ----
  // Learners and sessions are created before any work exists, so a failure throws sc::InputError
  // (the app shows it and can retry) instead of being queued.
  std::int64_t ensure_learner(std::string_view name, std::string_view created) override;
  std::int64_t begin_session(const NewSession& session) override;
  // One trainer per learner (learner_lock.hpp): a writable store claims the learner in begin_session and
  // find_unfinished_session, and holds the claim until it is destroyed. Throws sc::InputError when another
  // trainer holds them.
  void claim_learner(std::string_view name) const override;
  // These never throw for storage faults (see SaveResult); they throw sc::InputError for an invalid
  // record (unknown session, payload that is not JSON, empty task/device/timestamps, non-finite score).
  SaveResult record_trial(const TrialRecord& trial) override;  // assigns the next seq of the session
  SaveResult save_diagnosis(const DiagnosisRecord& diagnosis) override;
  SaveResult save_curriculum(const CurriculumRecord& curriculum) override;
  SaveResult save_progress(std::int64_t session_id, const SessionProgress& progress) override;
  SaveResult finish_session(std::int64_t session_id, std::string_view finished) override;
  // Retries the pending writes (reopening the database if it was read-only).
  SaveResult flush() override;
  std::size_t pending_count() const override { return pending_.size(); }
  // True when every pending write is also in the spill file, so it survives the end of the program.
  bool pending_spilled() const override { return pending_.empty() || spilled_; }
  // Non-empty when opening found something the user should know (e.g. an unreadable spill file).
  const std::string& open_message() const override { return open_message_; }

  // ---- resuming ----
  // The newest unfinished session of `learner` for `task` (any task if empty), with pending writes applied.
  // A writable store claims the learner first (claim_learner), so two trainers never resume one session.
  std::optional<ResumePoint> find_unfinished_session(std::string_view learner,
                                                     std::string_view task = {}) const override;
  // How many sessions of `task` the learner has begun (sessions are never pending: begin_session stores or
  // throws).
  int session_count(std::string_view learner, std::string_view task) const override;

  // ---- instructor review (database content only) ----
  std::optional<SessionRow> session(std::int64_t session_id) const override;
  std::vector<LearnerOverview> list_learners() const override;
  std::vector<StoredTrial> trials_of_session(std::int64_t session_id) const override;         // in seq order
  std::vector<DiagnosisRecord> diagnoses_of_session(std::int64_t session_id) const override;  // by round
  std::vector<CurriculumRecord> curricula_of_session(
      std::int64_t session_id) const override;  // by round, drills by index

  // ---- studies (study_records.hpp) ----
  // Like learners and sessions, these throw sc::InputError instead of queueing: a study and an enrolment
  // exist before any work. create_study refuses an invalid definition or a name in use.
  void create_study(const StudyDefinition& study) override;
  // Enrols `learner` with the next condition of the study's randomisation (an enrolled learner keeps their
  // place and condition); a full or unknown study is refused. One transaction: concurrent enrolments never
  // share a place.
  StudyParticipant enrol(std::string_view study, std::string_view learner, std::string_view enrolled) override;
  std::optional<StudyDefinition> study(std::string_view name) const override;
  std::vector<StudyDefinition> list_studies() const override;
  std::vector<StudyParticipant> study_participants(std::string_view study) const override;  // in enrolment order
  std::vector<SessionSummary> study_sessions(std::string_view study) const override;        // oldest first

 private:
  std::unique_ptr<SqliteDb> connect() const;
  std::unique_ptr<SqliteDb> connect_immutable() const;
  SqliteDb& connection() const;
  void reconnect();
  std::unique_ptr<SqliteDb> readable_schema(std::unique_ptr<SqliteDb> db) const;
  void load_spill_file();
  SaveResult submit(PendingWrite write);
  int next_seq(std::int64_t session_id);
  void require_session(std::int64_t session_id) const;
  bool try_write_pending(std::string& problem);
  std::string spill_pending();
  template <typename Fn>
  auto read(Fn&& query) const;  // runs a query; SQLite failures become sc::InputError
  template <typename Fn>
  auto write_now(const std::string& what, Fn&& write);  // one transaction; failures throw sc::InputError

  std::filesystem::path path_;
  StoreOptions options_;
  mutable std::unique_ptr<SqliteDb> db_;  // null only after a failed reconnect; connection() retries
  std::deque<PendingWrite> pending_;
  std::map<std::int64_t, int> last_seq_;  // per session: last seq handed out
  std::string open_message_;
  std::unique_ptr<LearnerLocks> locks_;  // mutable through the pointer: claims are not database content
  bool spilled_ = false;                 // the last spill_pending() wrote every pending write
  bool retryable_ = true;                // the last failed write was a storage fault (not e.g. a missing table)
};

}  // namespace sc::records
