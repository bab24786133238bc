// Which session counts for a participant and why a participant is left out.
#include "teaching/studies/study_outcomes.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

records::SessionSummary session(std::int64_t id, const std::string& learner, bool finished,
                                std::optional<double> pretest, std::optional<double> eval) {
  records::SessionSummary s;
  s.session.id = id;
  s.session.learner = learner;
  if (finished) s.session.finished = "2024-05-01T11:00:00.000Z";
  s.pretest_mean = pretest;
  s.eval_mean = eval;
  if (pretest && eval) s.improvement = *eval - *pretest;
  return s;
}

TEST(StudyOutcomes, TheFirstSessionCountsWhenFinishedWithBothScores) {
  const std::vector<records::StudyParticipant> participants{{"A", 1, "skills", ""},
                                                            {"B", 2, "drills", ""},
                                                            {"C", 3, "skills", ""},
                                                            {"D", 4, "drills", ""},
                                                            {"E", 5, "skills", ""}};
  const std::vector<records::SessionSummary> sessions{
      session(1, "A", true, -2.0, -1.0), session(2, "B", false, -2.0, std::nullopt),
      session(3, "A", true, -2.0, 5.0),  // a later session of A: ignored, whatever its result
      session(4, "C", true, -1.0, std::nullopt), session(5, "E", true, std::nullopt, -1.0)};
  const auto out = participant_outcomes(participants, sessions);
  ASSERT_EQ(out.size(), 5u);
  EXPECT_TRUE(out[0].counted());
  EXPECT_EQ(out[0].session_id, 1);
  EXPECT_DOUBLE_EQ(*out[0].improvement, 1.0);
  EXPECT_EQ(out[0].later_sessions, 1);
  EXPECT_EQ(out[1].excluded, "session 2 is unfinished");
  EXPECT_EQ(out[2].excluded, "session 4 has no evaluation score");
  EXPECT_EQ(out[3].excluded, "no session yet");
  EXPECT_EQ(out[4].excluded, "session 5 has no pre-test score");
}

}  // namespace
}  // namespace sc
