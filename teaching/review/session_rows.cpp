#include "teaching/review/session_rows.hpp"

#include <algorithm>
#include <cstdio>

#include "engine/core/error.hpp"
#include "engine/core/task_kind.hpp"
#include "teaching/sessions/session_settings.hpp"

namespace sc::review {
namespace {

std::optional<double> number_of(const SessionListRow& row, SessionColumn column) {
  switch (column) {
    case SessionColumn::Pretest:
      return row.pretest_mean;
    case SessionColumn::Evaluation:
      return row.eval_mean;
    case SessionColumn::Improvement:
      return row.improvement;
    default:
      return std::nullopt;
  }
}

const std::string& text_of(const SessionListRow& row, SessionColumn column) {
  switch (column) {
    case SessionColumn::Learner:
      return row.learner;
    case SessionColumn::Task:
      return row.task;
    case SessionColumn::Condition:
      return row.condition;
    default:
      return row.date;  // ISO-8601 text sorts chronologically
  }
}

bool is_numeric(SessionColumn column) {
  return column == SessionColumn::Pretest || column == SessionColumn::Evaluation ||
         column == SessionColumn::Improvement;
}

std::string format_number(double value, bool sign) {
  char text[32];
  std::snprintf(text, sizeof text, sign ? "%+.2f" : "%.2f", value);
  return text;
}

std::string lot_of(const records::SessionRow& session) {
  try {
    const std::optional<GoalRegion> region = settings_of_session(session).goal_region;
    // Parking sessions recorded before lots existed ran on the whole lot.
    if (!region) return task_kind_of(session.task) == TaskKind::parking ? "whole lot" : "";
    return *region == GoalRegion::StudyCorner ? "study corner" : "whole lot";
  } catch (const InputError&) {
    return "settings unreadable";  // the list still shows the session; opening it names the problem
  }
}

}  // namespace

std::string_view column_title(SessionColumn column) {
  switch (column) {
    case SessionColumn::Learner:
      return "Learner";
    case SessionColumn::Task:
      return "Task";
    case SessionColumn::Date:
      return "Date";
    case SessionColumn::Condition:
      return "Condition";
    case SessionColumn::Pretest:
      return "Pre-test";
    case SessionColumn::Evaluation:
      return "Evaluation";
    case SessionColumn::Improvement:
      return "Improvement";
  }
  return "";
}

std::vector<SessionListRow> session_rows(const std::vector<records::LearnerOverview>& learners) {
  std::vector<SessionListRow> rows;
  for (const auto& learner : learners)
    for (const auto& summary : learner.sessions) {
      SessionListRow row;
      row.session_id = summary.session.id;
      row.learner = learner.name;
      row.task = summary.session.task;
      row.lot = lot_of(summary.session);
      row.date = summary.session.started;
      row.condition = summary.session.condition;
      row.pretest_mean = summary.pretest_mean;
      row.eval_mean = summary.eval_mean;
      row.improvement = summary.improvement;
      row.trial_count = summary.trial_count;
      row.finished = summary.session.finished.has_value();
      rows.push_back(std::move(row));
    }
  return rows;
}

void sort_session_rows(std::vector<SessionListRow>& rows, SessionColumn column, bool ascending) {
  std::stable_sort(rows.begin(), rows.end(), [column, ascending](const SessionListRow& a, const SessionListRow& b) {
    if (is_numeric(column)) {
      const auto x = number_of(a, column), y = number_of(b, column);
      if (x.has_value() != y.has_value()) return x.has_value();  // missing values last
      if (!x || *x == *y) return a.session_id < b.session_id;
      return ascending ? *x < *y : *x > *y;
    }
    const std::string& x = text_of(a, column);
    const std::string& y = text_of(b, column);
    if (x == y) return a.session_id < b.session_id;
    return ascending ? x < y : x > y;
  });
}

std::string cell_text(const SessionListRow& row, SessionColumn column) {
  if (is_numeric(column)) {
    const auto value = number_of(row, column);
    return value ? format_number(*value, column == SessionColumn::Improvement) : "-";
  }
  if (column == SessionColumn::Date) {
    std::string date = row.date.substr(0, 16);  // "2024-05-01T10:00"
    if (date.size() > 10 && date[10] == 'T') date[10] = ' ';
    return date;
  }
  if (column == SessionColumn::Task && !row.lot.empty()) return row.task + ", " + row.lot;
  return text_of(row, column);
}

}  // namespace sc::review
