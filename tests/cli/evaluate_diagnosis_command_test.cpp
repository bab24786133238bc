// `skillcoach evaluate-diagnosis` end to end with the shipped parking model (what the rows mean is tested in
// tests/learners/parking/planted_deficit_recovery_test.cpp): its options and its refusals.
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_skillcoach.hpp"

namespace sc {
namespace {

using test::run_skillcoach;

int table_rows(const std::string& output) {
  int rows = 0;
  for (std::size_t at = output.find("\n| "); at != std::string::npos; at = output.find("\n| ", at + 1)) ++rows;
  return rows;
}

TEST(EvaluateDiagnosisCommand, LearnersWhoStandStillReadWholeAreSaidSoAboveTheTable) {
  const auto r = run_skillcoach(
      "evaluate-diagnosis --task parking --learners 2 --seed 14 --start-wait 1 --end-wait 5 --keeps-trying "
      "--keyboard-shift --read-whole-drives");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("each learner standing 1.0 s before driving"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("standing 5.0 s after driving"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("driving on until the time limit"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("keyboard learners steering gently with Shift"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("drives read whole"), std::string::npos) << r.output;
  EXPECT_EQ(table_rows(r.output), 8 + 1) << r.output;  // the header, then 4 deficits x 2 modes
  const auto plain = run_skillcoach("evaluate-diagnosis --task parking --learners 2 --seed 14");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find("standing"), std::string::npos) << plain.output;
  EXPECT_EQ(plain.output.find("Shift"), std::string::npos) << plain.output;
  EXPECT_EQ(plain.output.find("read whole"), std::string::npos) << plain.output;
  EXPECT_EQ(plain.output.find("one piece"), std::string::npos) << plain.output;
  // The shipped pool's longest drive moves for 26 control steps.
  EXPECT_NE(plain.output.find("drives of 39 steps or more read in pieces of about 26"), std::string::npos)
      << plain.output;
  const auto one_piece = run_skillcoach("evaluate-diagnosis --task parking --learners 2 --seed 14 --read-in-one-piece");
  ASSERT_EQ(one_piece.exit_code, 0) << one_piece.output;
  EXPECT_NE(one_piece.output.find("long drives read in one piece"), std::string::npos) << one_piece.output;
}

TEST(EvaluateDiagnosisCommand, ChargeRatesListEverySkillInsteadOfTheTable) {
  const auto r = run_skillcoach("evaluate-diagnosis --task parking --learners 2 --seed 14 --charge-rates");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("noise-only learners charged with each skill (Alg. 2, E_m < 0), of 2:"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("  skill 15: "), std::string::npos) << r.output;  // the shipped model's 16 skills
  EXPECT_EQ(table_rows(r.output), 0) << r.output;
}

TEST(EvaluateDiagnosisCommand, BadOptionsAreOneLineErrors) {
  for (const std::string bad : {"--task parking --start-wait -1", "--task parking --start-wait nan",
                                "--task parking --end-wait -2", "--task writing"}) {
    const auto r = run_skillcoach("evaluate-diagnosis " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
  }
}

}  // namespace
}  // namespace sc
