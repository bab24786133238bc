#pragma once
// The SQL that reads learner records back: resume points for the trainer and the instructor review's
// lists. Only what is in the database; the store adds its pending writes where that matters.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "teaching/records/pg_handle.hpp"
#include "teaching/records/record_types.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {

template <typename Db>
std::optional<SessionRow> query_session(Db& db, std::int64_t session_id);
// Unfinished sessions of a learner (for one task, or any task when `task` is empty), newest first.
template <typename Db>
std::vector<SessionRow> query_unfinished_sessions(Db& db, std::string_view learner, std::string_view task);
// Sessions of a learner for a task, finished or not (0 for an unknown learner).
template <typename Db>
int query_session_count(Db& db, std::string_view learner, std::string_view task);
template <typename Db>
int query_trial_count(Db& db, std::int64_t session_id);
template <typename Db>
int query_last_seq(Db& db, std::int64_t session_id);  // 0 when the session has no trial yet
template <typename Db>
std::vector<LearnerOverview> query_learners(Db& db);
// The sessions of a study (every participant's), oldest first, with their review summaries.
template <typename Db>
std::vector<SessionSummary> query_study_sessions(Db& db, std::string_view study);
template <typename Db>
std::vector<StoredTrial> query_trials(Db& db, std::int64_t session_id);
template <typename Db>
std::vector<DiagnosisRecord> query_diagnoses(Db& db, std::int64_t session_id);
template <typename Db>
std::vector<CurriculumRecord> query_curricula(Db& db, std::int64_t session_id);

}  // namespace sc::records
