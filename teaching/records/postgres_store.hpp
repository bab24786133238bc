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

#include "teaching/records/pending_writes.hpp"
#include "teaching/records/record_store.hpp"

namespace sc::records {

class PgDb;

class PostgresStore final : public RecordStore {
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

  std::int64_t ensure_learner(std::string_view name, std::string_view created) override;
  std::int64_t begin_session(const NewSession& session) override;
  void claim_learner(std::string_view name) const override;
  SaveResult record_trial(const TrialRecord& trial) override;
  SaveResult save_diagnosis(const DiagnosisRecord& diagnosis) override;
  SaveResult save_curriculum(const CurriculumRecord& curriculum) override;
  SaveResult save_progress(std::int64_t session_id, const SessionProgress& progress) override;
  SaveResult finish_session(std::int64_t session_id, std::string_view finished) override;
  SaveResult flush() override;
  std::size_t pending_count() const override { return pending_.size(); }
  bool pending_spilled() const override { return pending_.empty() || spilled_; }
  const std::string& open_message() const override { return open_message_; }

  std::optional<ResumePoint> find_unfinished_session(std::string_view learner,
                                                     std::string_view task = {}) const override;
  int session_count(std::string_view learner, std::string_view task) const override;

  std::optional<SessionRow> session(std::int64_t session_id) const override;
  std::vector<LearnerOverview> list_learners() const override;
  std::vector<StoredTrial> trials_of_session(std::int64_t session_id) const override;
  std::vector<DiagnosisRecord> diagnoses_of_session(std::int64_t session_id) const override;
  std::vector<CurriculumRecord> curricula_of_session(std::int64_t session_id) const override;

  void create_study(const StudyDefinition& study) override;
  StudyParticipant enrol(std::string_view study, std::string_view learner, std::string_view enrolled) override;
  std::optional<StudyDefinition> study(std::string_view name) const override;
  std::vector<StudyDefinition> list_studies() const override;
  std::vector<StudyParticipant> study_participants(std::string_view study) const override;
  std::vector<SessionSummary> study_sessions(std::string_view study) const override;

 private:
  PgDb& connection() const;
  void lock_learner(PgDb& db, const std::string& name) const;
  SaveResult submit(PendingWrite write);
  bool try_write_pending(std::string& problem);
  std::string spill_pending();
  void load_spill_file();
  int next_seq(std::int64_t session_id);
  void require_session(std::int64_t session_id) const;
  template <typename Fn>
  auto with_reconnect(Fn&& fn) const;
  template <typename Fn>
  auto read(Fn&& query) const;  // one retry on a fresh connection; failures become sc::InputError
  template <typename Fn>
  auto write_now(const std::string& what, Fn&& write);  // one transaction; failures throw sc::InputError

  std::string url_;
  std::filesystem::path label_;  // the URL without its password
  std::filesystem::path spill_;
  StoreOptions options_;
  mutable std::unique_ptr<PgDb> db_;  // null or broken after a lost connection; connection() reconnects
  mutable std::set<std::string, std::less<>> claimed_;
  std::deque<PendingWrite> pending_;
  std::map<std::int64_t, int> last_seq_;
  std::string open_message_;
  bool spilled_ = false;
  bool retryable_ = true;
};

}  // namespace sc::records
