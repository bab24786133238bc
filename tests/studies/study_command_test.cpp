// `skillcoach study`, `learn --study` and `study-report` end to end (the built program): a coordinator creates
// a study and enrols, a participant trains without being told the condition, a full study refuses, the report
// on the simulated cohort writes every file with the numbers of the in-process analysis, and bad input is one
// line with exit code 2.
#include <gtest/gtest.h>

#include "engine/core/json_file.hpp"
#include "engine/render/rgba_image.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/studies/study_analysis.hpp"
#include "tests/studies/study_cohort.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

TEST(StudyCommand, CreateEnrolLearnStatusAndAFullStudy) {
  const auto dir = test::fresh_scratch_dir("study-command");
  const std::string store = " --store " + quoted(dir);
  const auto created = test::run_skillcoach("study create" + store +
                                            " --name duo --task parking --conditions skills,Full\\ Trajectory"
                                            " --per-condition 1 --seed 5");
  ASSERT_EQ(created.exit_code, 0) << created.output;
  EXPECT_NE(created.output.find("created study \"duo\""), std::string::npos) << created.output;
  EXPECT_NE(created.output.find("2 conditions x 1 participants, seed 5"), std::string::npos) << created.output;

  const auto enrolled = test::run_skillcoach("study enrol" + store + " --study duo --learner Ada");
  ASSERT_EQ(enrolled.exit_code, 0) << enrolled.output;
  EXPECT_NE(enrolled.output.find("enrolled \"Ada\" in study \"duo\" as participant 1 of 2"), std::string::npos)
      << enrolled.output;

  const auto learned =
      test::run_skillcoach("learn --data-dir " + quoted(dir) + " --study duo --learner Ada --pretest 1 --eval 1");
  ASSERT_EQ(learned.exit_code, 0) << learned.output;
  // The participant is not told the condition.
  for (const char* hidden : {"skills", "Skills", "full-trajectory", "Full Trajectory", "condition"})
    EXPECT_EQ(learned.output.find(hidden), std::string::npos) << hidden << " in\n" << learned.output;
  {
    const records::LearnerStore s(dir, records::StoreOptions{.read_only = true});
    const auto sessions = s.study_sessions("duo");
    ASSERT_EQ(sessions.size(), 1u);
    EXPECT_EQ(sessions[0].session.condition, s.study_participants("duo")[0].condition);
    EXPECT_TRUE(sessions[0].session.finished);
  }
  const auto wrong_task =
      test::run_skillcoach("learn --data-dir " + quoted(dir) + " --study duo --learner Bo --task writing");
  EXPECT_EQ(wrong_task.exit_code, 2);
  EXPECT_EQ(wrong_task.output, "skillcoach: error: --task: study \"duo\" is a parking study\n");
  const auto again = test::run_skillcoach("learn --data-dir " + quoted(dir) + " --study duo --learner Ada");
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_EQ(again.output, "skillcoach: error: Ada: has already completed study \"duo\" (session 1)\n");

  ASSERT_EQ(test::run_skillcoach("study enrol" + store + " --study duo --learner Bo").exit_code, 0);
  const auto full = test::run_skillcoach("study enrol" + store + " --study duo --learner Cy");
  EXPECT_EQ(full.exit_code, 2);
  EXPECT_EQ(full.output,
            "skillcoach: error: study \"duo\": is full: all 2 places (1 per condition) are taken; \"Cy\" was not "
            "enrolled\n");

  const auto status = test::run_skillcoach("study status" + store + " --study duo");
  ASSERT_EQ(status.exit_code, 0) << status.output;
  EXPECT_NE(status.output.find("  skills                     1       1          "), std::string::npos) << status.output;
  EXPECT_NE(status.output.find("  total                      2       2          1  (full)"), std::string::npos)
      << status.output;

  // Bo is enrolled but has no session: no counted participant in one condition is reported, not refused.
  const auto no_sessions = test::run_skillcoach("study create" + store +
                                                " --name empty --task writing --conditions drills,ind-drills"
                                                " --per-condition 3");
  ASSERT_EQ(no_sessions.exit_code, 0) << no_sessions.output;
  const auto empty_report =
      test::run_skillcoach("study-report" + store + " --study empty --out " + quoted(dir / "empty-report"));
  EXPECT_EQ(empty_report.exit_code, 2);
  EXPECT_EQ(empty_report.output, "skillcoach: error: " + (dir / "skillcoach.db").string() +
                                     ": study \"empty\" has no finished session with pre-test and evaluation scores "
                                     "yet (0 enrolled)\n");
}

TEST(StudyReportCommand, WritesEveryFileWithTheAnalysisNumbers) {
  const auto& cohort = test::study_cohort();
  const auto out = test::fresh_scratch_dir("study-report-cohort");
  const auto result = test::run_skillcoach("study-report --store " + quoted(cohort.data_dir / "skillcoach.db") +
                                           " --study cohort --out " + quoted(out));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("study \"cohort\" (parking): 11 enrolled, 9 counted"), std::string::npos)
      << result.output;
  for (const char* file : {"participants.csv", "conditions.csv", "comparisons.csv", "study_report.json",
                           "improvement_parking.png", "study_report.html"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;

  const records::LearnerStore store(cohort.data_dir, records::StoreOptions{.read_only = true});
  const StudyAnalysis a = analyse_study(
      *store.study("cohort"), participant_outcomes(store.study_participants("cohort"), store.study_sessions("cohort")));
  const Json j = read_json_file(out / "study_report.json");
  ASSERT_EQ(j["conditions"].size(), a.conditions.size());
  for (std::size_t i = 0; i < a.conditions.size(); ++i) {
    EXPECT_EQ(j["conditions"][i]["improvement"]["n"], a.conditions[i].improvement.n);
    EXPECT_DOUBLE_EQ(j["conditions"][i]["improvement"]["mean"].get<double>(), a.conditions[i].improvement.mean);
  }
  for (std::size_t i = 0; i < a.comparisons.size(); ++i)
    EXPECT_DOUBLE_EQ(j["comparisons"][i]["p_holm"].get<double>(), a.comparisons[i].p_holm);
  const RgbaImage png = read_png(out / "improvement_parking.png");
  EXPECT_EQ(png.width, 1280);
  EXPECT_EQ(png.height, 720);
  EXPECT_NE(test::read_bytes(out / "study_report.html").find("src=\"data:image/png;base64,iVBORw0KGgo"),
            std::string::npos);
}

TEST(StudyReportCommand, BadInputIsOneLineAndExitCode2) {
  const auto out = test::fresh_scratch_dir("study-report-bad");
  records::LearnerStore(out / "data")
      .create_study({"pilot", "parking", {"skills", "drills"}, 2, 1, "2024-05-01T09:00:00.000Z"});
  const auto unknown =
      test::run_skillcoach("study-report --store " + quoted(out / "data") + " --study nope --out " + quoted(out));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.output,
            "skillcoach: error: " + (out / "data" / "skillcoach.db").string() + ": has no study \"nope\"\n");
  const auto missing =
      test::run_skillcoach("study-report --store " + quoted(out / "none") + " --study cohort --out " + quoted(out));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.output, "skillcoach: error: " + (out / "none" / "skillcoach.db").string() + ": no such database\n");
  test::write_bytes(out / "notes.txt", "not a database");
  const auto foreign = test::run_skillcoach("study-report --store " + quoted(out / "notes.txt") +
                                            " --study cohort --out " + quoted(out));
  EXPECT_EQ(foreign.exit_code, 2);
  EXPECT_EQ(foreign.output, "skillcoach: error: " + (out / "notes.txt").string() +
                                ": is neither a data directory nor a skillcoach.db file\n");
}

}  // namespace
}  // namespace sc
