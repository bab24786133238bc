// The report's tables and page from a small hand-made study: what each file holds, that a condition without
// counted participants is reported but not tested (and not counted in Holm's family), and that names are
// escaped.
#include "teaching/studies/study_report_files.hpp"

#include <gtest/gtest.h>

#include "teaching/studies/study_report_html.hpp"

namespace sc {
namespace {

ParticipantOutcome counted(int seq, const std::string& learner, const std::string& condition, double pre, double eval) {
  ParticipantOutcome o;
  o.participant = {learner, seq, condition, "2024-05-01T10:00:00.000Z"};
  o.session_id = seq;
  o.pretest_mean = pre;
  o.eval_mean = eval;
  o.improvement = eval - pre;
  return o;
}

StudyAnalysis small_study() {
  const records::StudyDefinition study{"small", "writing", {"skills", "time-heuristic", "full-trajectory"},
                                       2,       9,         "2024-05-01T09:00:00.000Z"};
  std::vector<ParticipantOutcome> outcomes{counted(1, "A, \"the first\"", "skills", -3.0, -1.0),
                                           counted(2, "<B>", "time-heuristic", -3.0, -2.5),
                                           counted(3, "C", "skills", -2.0, -1.0)};
  ParticipantOutcome left;
  left.participant = {"D", 4, "full-trajectory", "2024-05-01T10:00:00.000Z"};
  left.excluded = "no session yet";
  outcomes.push_back(left);
  return analyse_study(study, outcomes);
}

TEST(StudyReportFiles, ConditionsParticipantsAndComparisons) {
  const StudyAnalysis a = small_study();
  // skills: improvements 2 and 1 (mean 1.5, sd sqrt(0.5), se 0.5); time-heuristic: 0.5; full-trajectory: none.
  EXPECT_EQ(conditions_csv(a),
            "condition,name,target,enrolled,n,mean_improvement,se,sd,min,q1,median,q3,max,mean_pretest,mean_eval\n"
            "skills,Skills,2,2,2,1.5,0.5,0.70710678118654757,1,1.25,1.5,1.75,2,-2.5,-1\n"
            "time-heuristic,Time Heuristic,2,1,1,0.5,,,0.5,0.5,0.5,0.5,0.5,-3,-2.5\n"
            "full-trajectory,Full Trajectory,2,1,0,,,,,,,,,,\n");
  const std::string participants = participants_csv(a);
  EXPECT_NE(participants.find("1,\"A, \"\"the first\"\"\",skills,2024-05-01T10:00:00.000Z,1,-3,-1,2,yes,,0\n"),
            std::string::npos)
      << participants;
  EXPECT_NE(participants.find("4,D,full-trajectory,2024-05-01T10:00:00.000Z,,,,,no,no session yet,0\n"),
            std::string::npos)
      << participants;
  // Only skills vs time-heuristic is tested: U = 2 (both skills values beat 0.5), exact p = 2 * 1/3.
  ASSERT_EQ(a.comparisons.size(), 3u);
  EXPECT_FALSE(a.comparisons[0].test);  // skills vs full-trajectory
  ASSERT_TRUE(a.comparisons[1].test);
  EXPECT_DOUBLE_EQ(a.comparisons[1].test->u, 2.0);
  EXPECT_NEAR(a.comparisons[1].test->p, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(a.comparisons[1].p_holm, 2.0 / 3.0, 1e-12);  // a family of one
  EXPECT_EQ(comparisons_csv(a),
            "a,b,n_a,n_b,mean_difference,u,effect,method,z,p,p_holm,significant\n"
            "skills,full-trajectory,2,0,,,,not tested,,,,\n"
            "skills,time-heuristic,2,1,1,2,1,exact,,0.66666666666666663,0.66666666666666663,no\n"
            "time-heuristic,full-trajectory,1,0,,,,not tested,,,,\n");
}

TEST(StudyReportFiles, JsonAndSelfContainedHtml) {
  const StudyAnalysis a = small_study();
  const Json j = study_report_json(a);
  EXPECT_EQ(j["format"], "skillcoach-study-report");
  EXPECT_EQ(j["study"]["conditions"].size(), 3u);
  EXPECT_EQ(j["conditions"][0]["improvement"]["n"], 2);
  EXPECT_DOUBLE_EQ(j["conditions"][0]["improvement"]["se"].get<double>(), 0.5);
  EXPECT_TRUE(j["conditions"][1]["improvement"]["se"].is_null());
  EXPECT_EQ(j["comparisons"][1]["method"], "exact");
  EXPECT_EQ(j["participants"][3]["excluded"], "no session yet");
  const std::string html = study_report_html(a, {"improvement_writing.png", "PNGBYTES"});
  EXPECT_NE(html.find("src=\"data:image/png;base64,UE5HQllURVM=\""), std::string::npos);
  EXPECT_NE(html.find("&lt;B&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<B>"), std::string::npos);
  EXPECT_NE(html.find("Skills vs Time Heuristic"), std::string::npos);
}

}  // namespace
}  // namespace sc
