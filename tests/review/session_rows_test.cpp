#include "teaching/review/session_rows.hpp"

#include <gtest/gtest.h>

namespace sc::review {
namespace {

records::SessionSummary summary(std::int64_t id, const char* task, const char* started, std::optional<double> pre,
                                std::optional<double> eval) {
  records::SessionSummary s;
  s.session.id = id;
  s.session.task = task;
  s.session.condition = id % 2 ? "adaptive" : "skills";
  s.session.started = started;
  s.pretest_mean = pre;
  s.eval_mean = eval;
  if (pre && eval) s.improvement = *eval - *pre;
  s.trial_count = static_cast<int>(id) * 3;
  return s;
}

std::vector<SessionListRow> rows() {
  records::LearnerOverview ada{1, "Ada", "2024-05-01T09:00:00.000Z", {}};
  ada.sessions.push_back(summary(1, "parking", "2024-05-01T10:00:00.000Z", -3.0, -1.0));
  ada.sessions.push_back(summary(3, "writing", "2024-05-03T10:00:00.000Z", -0.5, std::nullopt));
  records::LearnerOverview bob{2, "Bob", "2024-05-01T09:00:00.000Z", {}};
  bob.sessions.push_back(summary(2, "parking", "2024-05-02T08:30:00.000Z", -2.0, -1.5));
  return session_rows({ada, bob});
}

std::vector<std::int64_t> ids(const std::vector<SessionListRow>& r) {
  std::vector<std::int64_t> out;
  for (const auto& row : r) out.push_back(row.session_id);
  return out;
}

TEST(SessionRows, OneRowPerSessionWithTheLearnersName) {
  const auto r = rows();
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[1].learner, "Ada");
  EXPECT_EQ(r[2].learner, "Bob");
  EXPECT_EQ(r[2].task, "parking");
  EXPECT_DOUBLE_EQ(*r[0].improvement, 2.0);
  EXPECT_FALSE(r[1].improvement.has_value());
}

TEST(SessionRows, AParkingSessionShowsItsLot) {
  records::LearnerOverview ada{1, "Ada", "2024-05-01T09:00:00.000Z", {}};
  const char* settings[] = {R"({"goal_region":"study-corner"})", "{}", R"({"goal_region":"corner"})", "{}"};
  for (int i = 0; i < 4; ++i) {
    ada.sessions.push_back(summary(i + 1, i == 3 ? "writing" : "parking", "2024-05-01T10:00:00.000Z", -1.0, -0.5));
    ada.sessions.back().session.learner = "Ada";
    ada.sessions.back().session.settings_json = settings[i];
  }
  const auto r = session_rows({ada});
  EXPECT_EQ(cell_text(r[0], SessionColumn::Task), "parking, study corner");
  EXPECT_EQ(cell_text(r[1], SessionColumn::Task), "parking, whole lot");  // recorded before lots existed
  EXPECT_EQ(cell_text(r[2], SessionColumn::Task), "parking, settings unreadable");
  EXPECT_EQ(cell_text(r[3], SessionColumn::Task), "writing");
}

TEST(SessionRows, SortsByEveryColumnBothWays) {
  auto r = rows();
  sort_session_rows(r, SessionColumn::Date, true);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{1, 2, 3}));
  sort_session_rows(r, SessionColumn::Date, false);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{3, 2, 1}));
  sort_session_rows(r, SessionColumn::Learner, false);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{2, 1, 3}));  // Bob, then Ada's two in id order
  sort_session_rows(r, SessionColumn::Task, true);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{1, 2, 3}));
  sort_session_rows(r, SessionColumn::Pretest, true);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{1, 2, 3}));
  sort_session_rows(r, SessionColumn::Condition, true);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{1, 3, 2}));
}

TEST(SessionRows, MissingValuesComeLastInBothDirections) {
  auto r = rows();
  sort_session_rows(r, SessionColumn::Improvement, false);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{1, 2, 3}));
  sort_session_rows(r, SessionColumn::Improvement, true);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{2, 1, 3}));
  sort_session_rows(r, SessionColumn::Evaluation, true);
  EXPECT_EQ(ids(r), (std::vector<std::int64_t>{2, 1, 3}));
}

TEST(SessionRows, CellsAreReadable) {
  const auto r = rows();
  EXPECT_EQ(cell_text(r[0], SessionColumn::Date), "2024-05-01 10:00");
  EXPECT_EQ(cell_text(r[0], SessionColumn::Improvement), "+2.00");
  EXPECT_EQ(cell_text(r[0], SessionColumn::Pretest), "-3.00");
  EXPECT_EQ(cell_text(r[1], SessionColumn::Evaluation), "-");
  EXPECT_EQ(column_title(SessionColumn::Pretest), "Pre-test");
}

}  // namespace
}  // namespace sc::review
