#pragma once
// Which sessions an instructor looks at. A class's shared store holds every learner's sessions (one
// database per class, README "A class on one server"); the review's session list narrows them by learner,
// task and date, as `skillcoach report` does with --learner, --from and --to.
//
// Spec: a row matches when its learner's name contains `learner` (ASCII case-insensitive; empty matches
// everyone), its task is `task` (empty: any), and its start date (ISO-8601, as stored) lies within [from, to],
// each bound an ISO date or date-time prefix compared on its own length, so to = "2026-12-03" includes the
// whole of that day. A bound that is not such a prefix (valid_date_bound) is ignored by matches; the list
// shows it as an error instead.
#include <string>
#include <vector>

#include "teaching/review/session_rows.hpp"

namespace sc::review {

struct SessionFilter {
  std::string learner;
  std::string task;  // "parking", "writing" or empty
  std::string from, to;
};

// Empty, or "YYYY", "YYYY-MM", "YYYY-MM-DD", optionally followed by "T" or " " and a time ("HH", "HH:MM", ...),
// each field in its range (month 1-12, day 1-31, hour 0-23, ...).
bool valid_date_bound(const std::string& bound);

bool matches(const SessionListRow& row, const SessionFilter& filter);

// The rows that match, in their order.
std::vector<SessionListRow> filtered_rows(const std::vector<SessionListRow>& rows, const SessionFilter& filter);

}  // namespace sc::review
