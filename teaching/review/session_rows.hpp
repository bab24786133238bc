#pragma once
// The instructor's session browser: one row per session (learner, task, date, condition, pre-test and
// evaluation mean scores, improvement), sortable by any column. The means are the store's review summary
// (docs/database.md, "Review summaries"); a session without a pre-test or evaluation yet has no value there.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "teaching/records/record_types.hpp"

namespace sc::review {

struct SessionListRow {
  std::int64_t session_id = 0;
  std::string learner;
  std::string task;
  std::string lot;   // parking: "study corner" or "whole lot" (the session's goal_region); writing: empty
  std::string date;  // the session's start, ISO-8601 UTC as stored
  std::string condition;
  std::optional<double> pretest_mean;
  std::optional<double> eval_mean;
  std::optional<double> improvement;
  int trial_count = 0;
  bool finished = false;
};

enum class SessionColumn { Learner, Task, Date, Condition, Pretest, Evaluation, Improvement };
inline constexpr SessionColumn kSessionColumns[] = {
    SessionColumn::Learner, SessionColumn::Task,       SessionColumn::Date,       SessionColumn::Condition,
    SessionColumn::Pretest, SessionColumn::Evaluation, SessionColumn::Improvement};

std::string_view column_title(SessionColumn column);  // "Learner", "Pre-test", ...

// Every session of every learner, in the store's order (learners by name, sessions oldest first).
std::vector<SessionListRow> session_rows(const std::vector<records::LearnerOverview>& learners);

// Stable sort by one column. Rows without a value in that column (no pre-test yet, ...) always come last,
// whatever the direction, so an instructor sorting by improvement sees measured sessions first; ties keep
// session id order.
void sort_session_rows(std::vector<SessionListRow>& rows, SessionColumn column, bool ascending);

// The cell as text: names as they are (a parking task with its lot: "parking, study corner"), the date as "2024-05-01
// 10:00", scores with 2 decimals ("-3.12"; improvement signed "+1.90"), "-" when missing.
std::string cell_text(const SessionListRow& row, SessionColumn column);

}  // namespace sc::review
