#include "teaching/review/session_filter.hpp"

#include <gtest/gtest.h>

namespace sc::review {
namespace {

SessionListRow row(std::int64_t id, const char* learner, const char* task, const char* date) {
  SessionListRow r;
  r.session_id = id;
  r.learner = learner;
  r.task = task;
  r.date = date;
  return r;
}

const std::vector<SessionListRow> kClass = {
    row(1, "Ada Lovelace", "parking", "2026-12-01T10:00:00.000Z"), row(2, "Bob", "writing", "2026-12-02T08:30:00.000Z"),
    row(3, "ada", "writing", "2026-12-03T23:59:00.000Z"), row(4, "Cleo", "parking", "2026-12-04T00:00:00.000Z")};

std::vector<std::int64_t> ids(const SessionFilter& filter) {
  std::vector<std::int64_t> out;
  for (const auto& r : filtered_rows(kClass, filter)) out.push_back(r.session_id);
  return out;
}

TEST(SessionFilter, AnEmptyFilterKeepsEverySessionInOrder) {
  EXPECT_EQ(ids({}), (std::vector<std::int64_t>{1, 2, 3, 4}));
}

TEST(SessionFilter, LearnerIsACaseInsensitivePartOfTheName) {
  EXPECT_EQ(ids({"ADA", "", "", ""}), (std::vector<std::int64_t>{1, 3}));
  EXPECT_EQ(ids({"love", "", "", ""}), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(ids({"Zed", "", "", ""}), (std::vector<std::int64_t>{}));
}

TEST(SessionFilter, TaskAndLearnerCombine) {
  EXPECT_EQ(ids({"", "writing", "", ""}), (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(ids({"ada", "parking", "", ""}), (std::vector<std::int64_t>{1}));
}

TEST(SessionFilter, DateBoundsAreInclusiveAndADateMeansTheWholeDay) {
  EXPECT_EQ(ids({"", "", "2026-12-02", ""}), (std::vector<std::int64_t>{2, 3, 4}));
  EXPECT_EQ(ids({"", "", "", "2026-12-03"}), (std::vector<std::int64_t>{1, 2, 3}));  // 23:59 on the 3rd is in
  EXPECT_EQ(ids({"", "", "2026-12-02", "2026-12-03"}), (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(ids({"", "", "2026-12-02 09:00", ""}), (std::vector<std::int64_t>{3, 4}));  // a space for the T
  EXPECT_EQ(ids({"", "", "2026-12", "2026-12"}), (std::vector<std::int64_t>{1, 2, 3, 4}));
}

TEST(SessionFilter, OnlyIsoDatePrefixesAreBounds) {
  for (const char* good :
       {"", "2026", "2026-12", "2026-12-03", "2026-12-03T10", "2026-12-03 10:15", "2026-12-03T10:15:00"})
    EXPECT_TRUE(valid_date_bound(good)) << good;
  for (const char* bad : {"yesterday", "2026-1", "03/12/2026", "2026-12-03T", "2026-12-3", "2026-12-03T10:15:00Z+",
                          "2026-13", "2026-00-01", "2026-12-32", "2026-12-03T24"})
    EXPECT_FALSE(valid_date_bound(bad)) << bad;
  // A bound that is not a date narrows nothing (the list says so instead of showing no sessions).
  EXPECT_EQ(ids({"", "", "yesterday", ""}), (std::vector<std::int64_t>{1, 2, 3, 4}));
}

}  // namespace
}  // namespace sc::review
