#include "teaching/review/session_filter.hpp"

#include <algorithm>
#include <cctype>

namespace sc::review {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// `pattern`: 'd' a digit, anything else itself; `text` must be a prefix of it ending at a field boundary.
bool matches_prefix_of(const std::string& text, const std::string& pattern) {
  if (text.size() > pattern.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool digit = std::isdigit(static_cast<unsigned char>(text[i])) != 0;
    if (pattern[i] == 'd' ? !digit : text[i] != pattern[i]) return false;
  }
  return text.size() == pattern.size() || pattern[text.size()] != 'd';
}

// The two-digit field at `at` of an ISO date-time, when `text` has it, lies in [lo, hi].
bool field_in(const std::string& text, std::size_t at, int lo, int hi) {
  if (text.size() < at + 2) return true;
  const int value = std::stoi(text.substr(at, 2));
  return value >= lo && value <= hi;
}

}  // namespace

bool valid_date_bound(const std::string& bound) {
  if (bound.empty()) return true;
  std::string normalised = bound;
  if (normalised.size() > 10 && normalised[10] == ' ') normalised[10] = 'T';
  if (normalised.size() == 11 || !matches_prefix_of(normalised, "dddd-dd-ddTdd:dd:dd")) return false;
  return field_in(normalised, 5, 1, 12) && field_in(normalised, 8, 1, 31) && field_in(normalised, 11, 0, 23) &&
         field_in(normalised, 14, 0, 59) && field_in(normalised, 17, 0, 60);
}

bool matches(const SessionListRow& row, const SessionFilter& filter) {
  if (!filter.learner.empty() && lower(row.learner).find(lower(filter.learner)) == std::string::npos) return false;
  if (!filter.task.empty() && row.task != filter.task) return false;
  auto normalised = [](std::string bound) {
    if (bound.size() > 10 && bound[10] == ' ') bound[10] = 'T';
    return bound;
  };
  if (valid_date_bound(filter.from) && !filter.from.empty()) {
    const std::string from = normalised(filter.from);
    if (row.date.compare(0, from.size(), from) < 0) return false;
  }
  if (valid_date_bound(filter.to) && !filter.to.empty()) {
    const std::string to = normalised(filter.to);
    if (row.date.compare(0, to.size(), to) > 0) return false;
  }
  return true;
}

std::vector<SessionListRow> filtered_rows(const std::vector<SessionListRow>& rows, const SessionFilter& filter) {
  std::vector<SessionListRow> out;
  std::copy_if(rows.begin(), rows.end(), std::back_inserter(out),
               [&](const SessionListRow& row) { return matches(row, filter); });
  return out;
}

}  // namespace sc::review
