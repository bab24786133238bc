#pragma once
// QueuedRecordStore: the part of a RecordStore that does not depend on the database, written once for
// LearnerStore (SQLite) and PostgresStore (PostgreSQL): the validated trainer writes, the queue of pending
// writes with its spill file, sequence numbers per session, resuming with pending writes applied, and the
// reads (record_queries.hpp), all over the handle type `Db` whose failures throw `DbError`.
//
// Why a template over the handle (CRTP) rather than a virtual database: the record SQL (record_queries,
// record_writes, record_studies) is already written once as templates over the handle, and what differs
// between the two stores is only how a connection is made, kept and retried. The derived store provides:
//   Db& connection() const;                          a usable connection (reconnecting if it must)
//   template <typename Fn> auto read(Fn&&) const;    runs a query; database failures -> sc::InputError
//   template <typename Fn> auto write_now(const std::string& what, Fn&&);   one transaction, or InputError
//   bool try_write_pending(std::string& problem);    writes the queue in order; on failure says why and
//                                                    sets retryable_
//   std::string unsaved_words() const;               "not saved yet", "not saved on the server yet"
//   std::string retry_note() const;                  what happens next, given retryable_
// and the RecordStore members that are its own (paths, schema version, claim_learner, enrol).
//
// The member definitions are in queued_record_store_impl.hpp, instantiated once in each store's .cpp.
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "teaching/records/pending_writes.hpp"
#include "teaching/records/record_store.hpp"

namespace sc::records {

template <typename Derived, typename Db, typename DbError>
class QueuedRecordStore : public RecordStore {
 public:
  std::int64_t ensure_learner(std::string_view name, std::string_view created) override;
  std::int64_t begin_session(const NewSession& session) override;
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
  std::optional<StudyDefinition> study(std::string_view name) const override;
  std::vector<StudyDefinition> list_studies() const override;
  std::vector<StudyParticipant> study_participants(std::string_view study) const override;
  std::vector<SessionSummary> study_sessions(std::string_view study) const override;

 protected:
  explicit QueuedRecordStore(StoreOptions options) : options_(options) {}
  // Reads the spill file a previous store left (an unreadable one is moved aside and open_message_ says so),
  // then tries to write its records; call from the derived constructor once connected.
  void replay_spill_file();

  StoreOptions options_;
  std::deque<PendingWrite> pending_;
  std::string open_message_;
  bool retryable_ = true;  // the last failed write was a passing fault (not e.g. a missing table)

 private:
  Derived& derived() { return static_cast<Derived&>(*this); }
  const Derived& derived() const { return static_cast<const Derived&>(*this); }
  SaveResult submit(PendingWrite write);
  std::string spill_pending();
  int next_seq(std::int64_t session_id);
  void require_session(std::int64_t session_id) const;

  std::map<std::int64_t, int> last_seq_;  // per session: last seq handed out
  bool spilled_ = false;                  // the last spill_pending() wrote every pending write
};

}  // namespace sc::records
