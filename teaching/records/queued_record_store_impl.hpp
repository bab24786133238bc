#pragma once
// Member definitions of QueuedRecordStore (queued_record_store.hpp). Include only from a store's .cpp,
// after the handle's header, and instantiate there explicitly.
#include <filesystem>

#include "engine/core/error.hpp"
#include "teaching/records/queued_record_store.hpp"
#include "teaching/records/record_queries.hpp"
#include "teaching/records/record_studies.hpp"
#include "teaching/records/record_validation.hpp"
#include "teaching/records/record_writes.hpp"

namespace sc::records {

template <typename D, typename Db, typename E>
void QueuedRecordStore<D, Db, E>::replay_spill_file() {
  const auto spill = spill_path();
  std::error_code ec;
  if (std::filesystem::exists(spill, ec)) {
    try {
      for (auto& write : read_spill_file(spill)) pending_.push_back(std::move(write));
    } catch (const InputError& e) {
      // Never overwrite what may be a learner's only copy of a trial: move it aside and say so.
      auto aside = spill;
      aside += ".unreadable";
      for (int n = 2; std::filesystem::exists(aside, ec); ++n) {
        aside = spill;
        aside += ".unreadable" + std::to_string(n);
      }
      std::filesystem::rename(spill, aside, ec);
      open_message_ = std::string(e.what()) + (ec ? "; left in place" : "; moved to " + aside.string());
    }
  }
  if (pending_.empty()) return;
  const auto result = flush();
  if (!result.message.empty()) open_message_ += (open_message_.empty() ? "" : "; ") + result.message;
}

template <typename D, typename Db, typename E>
std::int64_t QueuedRecordStore<D, Db, E>::ensure_learner(std::string_view name, std::string_view created) {
  require_learner_name(name);
  require_text(created, "learner creation time");
  return derived().write_now("save learner \"" + std::string(name) + "\"",
                             [&](Db& db) { return insert_learner_if_new(db, name, created); });
}

template <typename D, typename Db, typename E>
std::int64_t QueuedRecordStore<D, Db, E>::begin_session(const NewSession& session) {
  validate_new_session(session);
  claim_learner(session.learner);
  const auto id = derived().write_now("start a session for \"" + session.learner + "\"", [&](Db& db) {
    const auto session_id = insert_session(db, insert_learner_if_new(db, session.learner, session.started), session);
    if (!session.study.empty()) attach_session_to_study(db, session_id, session);
    return session_id;
  });
  last_seq_[id] = 0;
  return id;
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::record_trial(const TrialRecord& trial) {
  require_session(trial.session_id);
  validate_trial(trial);
  return submit(TrialWrite{trial, next_seq(trial.session_id)});
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::save_diagnosis(const DiagnosisRecord& diagnosis) {
  require_session(diagnosis.session_id);
  validate_diagnosis(diagnosis);
  return submit(diagnosis);
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::save_curriculum(const CurriculumRecord& curriculum) {
  require_session(curriculum.session_id);
  validate_curriculum(curriculum);
  return submit(curriculum);
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::save_progress(std::int64_t session_id, const SessionProgress& progress) {
  require_session(session_id);
  validate_progress(progress);
  return submit(ProgressWrite{session_id, progress});
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::finish_session(std::int64_t session_id, std::string_view finished) {
  require_session(session_id);
  require_text(finished, "session end time");
  return submit(FinishWrite{session_id, std::string(finished)});
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::submit(PendingWrite write) {
  pending_.push_back(std::move(write));
  return flush();  // the new write is last in the queue, so it is stored iff the queue empties
}

template <typename D, typename Db, typename E>
SaveResult QueuedRecordStore<D, Db, E>::flush() {
  if (pending_.empty()) return {true, 0, {}};
  std::string problem;
  if (derived().try_write_pending(problem)) {
    std::error_code ec;
    std::filesystem::remove(spill_path(), ec);  // everything it held is in the database now
    return {true, 0, {}};
  }
  const auto count = pending_.size();
  return {false, count,
          database_path().string() + ": " + std::to_string(count) + (count == 1 ? " record " : " records ") +
              derived().unsaved_words() + " (" + problem + "); " + spill_pending() + "; " + derived().retry_note()};
}

template <typename D, typename Db, typename E>
std::string QueuedRecordStore<D, Db, E>::spill_pending() {
  spilled_ = false;
  if (options_.read_only) return "kept in memory only (store opened read-only)";
  try {
    write_spill_file(spill_path(), database_path(), pending_);
    spilled_ = true;
    return "kept in memory and in " + spill_path().string();
  } catch (const InputError& e) {
    return std::string("kept in memory only (") + e.what() + ")";
  }
}

template <typename D, typename Db, typename E>
int QueuedRecordStore<D, Db, E>::next_seq(std::int64_t session_id) {
  auto it = last_seq_.find(session_id);
  if (it == last_seq_.end()) {
    int last = 0;
    try {
      last = query_last_seq(derived().connection(), session_id);
    } catch (const E&) {  // unreachable now: the pending queue below still orders this session
    }
    it = last_seq_.emplace(session_id, last_seq_with_pending(pending_, session_id, last)).first;
  }
  return ++it->second;
}

template <typename D, typename Db, typename E>
void QueuedRecordStore<D, Db, E>::require_session(std::int64_t session_id) const {
  if (last_seq_.count(session_id) != 0) return;
  bool known = true;
  try {
    known = query_session(derived().connection(), session_id).has_value();
  } catch (const E&) {  // cannot check now; a write for an unknown session would stay pending
  }
  if (!known) throw InputError(database_path().string(), "unknown session id " + std::to_string(session_id));
}

template <typename D, typename Db, typename E>
std::optional<ResumePoint> QueuedRecordStore<D, Db, E>::find_unfinished_session(std::string_view learner,
                                                                                std::string_view task) const {
  claim_learner(learner);
  const auto sessions = derived().read([&](Db& db) { return query_unfinished_sessions(db, learner, task); });
  for (const auto& row : sessions) {
    ResumePoint point{row, derived().read([&](Db& db) { return query_trial_count(db, row.id); })};
    if (!apply_pending_to_resume(point, pending_)) return point;  // pending writes are the learner's work too
  }
  return std::nullopt;
}

template <typename D, typename Db, typename E>
int QueuedRecordStore<D, Db, E>::session_count(std::string_view learner, std::string_view task) const {
  return derived().read([&](Db& db) { return query_session_count(db, learner, task); });
}

template <typename D, typename Db, typename E>
std::optional<SessionRow> QueuedRecordStore<D, Db, E>::session(std::int64_t session_id) const {
  return derived().read([&](Db& db) { return query_session(db, session_id); });
}

template <typename D, typename Db, typename E>
std::vector<LearnerOverview> QueuedRecordStore<D, Db, E>::list_learners() const {
  return derived().read([](Db& db) { return query_learners(db); });
}

template <typename D, typename Db, typename E>
std::vector<StoredTrial> QueuedRecordStore<D, Db, E>::trials_of_session(std::int64_t session_id) const {
  return derived().read([&](Db& db) { return query_trials(db, session_id); });
}

template <typename D, typename Db, typename E>
std::vector<DiagnosisRecord> QueuedRecordStore<D, Db, E>::diagnoses_of_session(std::int64_t session_id) const {
  return derived().read([&](Db& db) { return query_diagnoses(db, session_id); });
}

template <typename D, typename Db, typename E>
std::vector<CurriculumRecord> QueuedRecordStore<D, Db, E>::curricula_of_session(std::int64_t session_id) const {
  return derived().read([&](Db& db) { return query_curricula(db, session_id); });
}

template <typename D, typename Db, typename E>
void QueuedRecordStore<D, Db, E>::create_study(const StudyDefinition& study) {
  validate_study(study);
  derived().write_now("create study \"" + study.name + "\"", [&](Db& db) {
    insert_study(db, study);
    return 0;
  });
}

template <typename D, typename Db, typename E>
std::optional<StudyDefinition> QueuedRecordStore<D, Db, E>::study(std::string_view name) const {
  return derived().read([&](Db& db) { return query_study(db, name); });
}

template <typename D, typename Db, typename E>
std::vector<StudyDefinition> QueuedRecordStore<D, Db, E>::list_studies() const {
  return derived().read([](Db& db) { return query_studies(db); });
}

template <typename D, typename Db, typename E>
std::vector<StudyParticipant> QueuedRecordStore<D, Db, E>::study_participants(std::string_view study) const {
  return derived().read([&](Db& db) { return query_participants(db, study); });
}

template <typename D, typename Db, typename E>
std::vector<SessionSummary> QueuedRecordStore<D, Db, E>::study_sessions(std::string_view study) const {
  return derived().read([&](Db& db) { return query_study_sessions(db, study); });
}

}  // namespace sc::records
