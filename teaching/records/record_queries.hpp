#pragma once
// The SQL that reads learner records back: resume points for the trainer and the instructor review's
// lists. Only what is in the database; the store adds its pending writes where that matters.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "teaching/records/record_types.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {

std::optional<SessionRow> query_session(SqliteDb& db, std::int64_t session_id);
// Unfinished sessions of a learner (for one task, or any task when `task` is empty), newest first.
std::vector<SessionRow> query_unfinished_sessions(SqliteDb& db, std::string_view learner, std::string_view task);
// Sessions of a learner for a task, finished or not (0 for an unknown learner).
int query_session_count(SqliteDb& db, std::string_view learner, std::string_view task);
int query_trial_count(SqliteDb& db, std::int64_t session_id);
int query_last_seq(SqliteDb& db, std::int64_t session_id);  // 0 when the session has no trial yet
std::vector<LearnerOverview> query_learners(SqliteDb& db);
// The sessions of a study (every participant's), oldest first, with their review summaries.
std::vector<SessionSummary> query_study_sessions(SqliteDb& db, std::string_view study);
std::vector<StoredTrial> query_trials(SqliteDb& db, std::int64_t session_id);
std::vector<DiagnosisRecord> query_diagnoses(SqliteDb& db, std::int64_t session_id);
std::vector<CurriculumRecord> query_curricula(SqliteDb& db, std::int64_t session_id);

}  // namespace sc::records
