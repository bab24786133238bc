// `skillcoach evaluate-skills` end to end on tiny models (the numbers are checked for shape and range here;
// their meaning is tested in tests/tasks/skill_quality_test.cpp).
#include <gtest/gtest.h>

#include "tests/cli/skills_cli_fixture.hpp"

namespace sc {
namespace {

using test::run_skillcoach;

Json report_json_of(const std::string& output) {
  const auto start = output.find("\n{");
  EXPECT_NE(start, std::string::npos) << output;
  return Json::parse(output.substr(start == std::string::npos ? 0 : start + 1));
}

TEST(EvaluateSkillsCommand, WritingReportsBoundaryScoresUsageAndReconstructionOnHeldOutWords) {
  const auto r =
      run_skillcoach("evaluate-skills --task writing --count 10 --model " + test::tiny_model("writing").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json d = report_json_of(r.output);
  EXPECT_EQ(d.at("seed"), 4);  // the model's seed (3) + 1: not its training data
  EXPECT_EQ(d.at("trajectories"), 10);
  const Json& b = d.at("boundaries");
  // 8-symbol words have 7 interior character boundaries each.
  EXPECT_EQ(b.at("true_positives").get<int>() + b.at("false_negatives").get<int>(), 70);
  EXPECT_GE(b.at("f1").get<double>(), 0.0);
  EXPECT_LE(b.at("f1").get<double>(), 1.0);
  EXPECT_GE(d.at("usage").at("skills_used").get<int>(), 1);
  EXPECT_GT(d.at("usage").at("mean_segment_length").get<double>(), 0.0);
  EXPECT_GT(d.at("action_reconstruction_error").get<double>(), 0.0);
  EXPECT_FALSE(d.contains("purity"));
}

TEST(EvaluateSkillsCommand, DetailsListEveryWordWithItsTrueBoundariesAndContiguousSegments) {
  const auto plain =
      run_skillcoach("evaluate-skills --task writing --count 3 --model " + test::tiny_model("writing").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_FALSE(report_json_of(plain.output).contains("demos"));
  const auto r = run_skillcoach("evaluate-skills --task writing --count 3 --details --model " +
                                test::tiny_model("writing").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json demos = report_json_of(r.output).at("demos");
  ASSERT_EQ(demos.size(), 3u);
  for (const Json& d : demos) {
    EXPECT_EQ(d.at("label").get<std::string>().size(), 8u) << d;  // an 8-symbol word
    EXPECT_EQ(d.at("true_boundaries").size(), 7u) << d;
    // Segments [skill, begin, end] tile [0, steps) in order.
    int next = 0;
    for (const Json& s : d.at("segments")) {
      EXPECT_EQ(s.at(1).get<int>(), next) << d;
      EXPECT_GT(s.at(2).get<int>(), s.at(1).get<int>()) << d;
      next = s.at(2).get<int>();
    }
    EXPECT_EQ(next, d.at("steps").get<int>()) << d;
  }
}

TEST(EvaluateSkillsCommand, ParkingReportsPurityPerSkill) {
  const auto r =
      run_skillcoach("evaluate-skills --task parking --count 4 --model " + test::tiny_model("parking").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json d = report_json_of(r.output);
  ASSERT_FALSE(d.at("purity").at("per_skill").empty());
  for (const Json& p : d.at("purity").at("per_skill")) {
    EXPECT_NEAR(p.at("reversing").get<double>() + p.at("forward").get<double>(), 1.0, 1e-9);
    EXPECT_NEAR(p.at("left").get<double>() + p.at("right").get<double>() + p.at("straight").get<double>(), 1.0, 1e-9);
  }
  EXPECT_FALSE(d.contains("boundaries"));
}

TEST(EvaluateSkillsCommand, ParkingRealisticDriversGiveOneAgreementPerCondition) {
  const auto r = run_skillcoach("evaluate-skills --task parking --count 3 --realistic-drivers --model " +
                                test::tiny_model("parking").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json rows = report_json_of(r.output).at("realistic_drivers");
  // 8 open loop, 7 following the path, 4 standing still at the start or end, 1 driving on until 15 s, 2 keyboards
  // with Shift for gentle steering
  ASSERT_EQ(rows.size(), 22u);
  // 15 Hz input without noise or delay changes nothing a skill model sees, beyond the gamepad's dead zone.
  EXPECT_GE(rows[0].at("agreement").get<double>(), 0.9) << rows[0];
  EXPECT_NE(rows[8].at("condition").get<std::string>().find("follows the path"), std::string::npos) << rows[8];
  // The expert's motion a reaction delay late, compared a delay later, agrees as the drive on time does.
  EXPECT_EQ(rows[15].at("condition"), "gamepad, no noise, delay 0.2 s, 15 Hz");
  EXPECT_DOUBLE_EQ(rows[15].at("agreement").get<double>(), rows[0].at("agreement").get<double>());
  EXPECT_NE(rows[19].at("condition").get<std::string>().find("keeps trying"), std::string::npos) << rows[19];
  EXPECT_EQ(rows[20].at("condition"), "keyboard with Shift, no noise, no delay, 15 Hz");
  const Json limits = report_json_of(r.output).at("expert_actions_at_limits");
  EXPECT_GT(limits.at("steps").get<int>(), 0) << limits;
  EXPECT_GE(limits.at("pedal").get<double>(), 0.0) << limits;
  EXPECT_LE(limits.at("pedal").get<double>(), 1.0) << limits;
  for (const Json& row : rows) {
    EXPECT_GE(row.at("agreement").get<double>(), 0.0) << row;
    EXPECT_LE(row.at("agreement").get<double>(), 1.0) << row;
    EXPECT_GT(row.at("steps").get<int>(), 0) << row;
  }
  const auto writing = run_skillcoach("evaluate-skills --task writing --count 2 --realistic-drivers --model " +
                                      test::tiny_model("writing").string());
  EXPECT_EQ(writing.exit_code, 2) << writing.output;
}

TEST(EvaluateSkillsCommand, RefusesTheTrainingSeedAndAModelOfAnotherTask) {
  const auto same =
      run_skillcoach("evaluate-skills --task writing --seed 3 --model " + test::tiny_model("writing").string());
  EXPECT_EQ(same.exit_code, 2) << same.output;
  EXPECT_NE(same.output.find("seed the model was trained with"), std::string::npos) << same.output;
  const auto other = run_skillcoach("evaluate-skills --task parking --model " + test::tiny_model("writing").string());
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_EQ(test::count_lines(other.output), 1) << other.output;
}

TEST(EvaluateSkillsCommand, TimeHeuristicIsScoredAsTheBaselineWithoutAModel) {
  const auto r = run_skillcoach("evaluate-skills --task writing --count 4 --time-heuristic --details");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json d = report_json_of(r.output);
  EXPECT_EQ(d.at("extractor"), "time-heuristic (8 equal segments)");
  EXPECT_EQ(d.at("seed"), 1);
  EXPECT_FALSE(d.contains("action_reconstruction_error"));
  EXPECT_FALSE(d.contains("model"));
  const Json& b = d.at("boundaries");
  EXPECT_EQ(b.at("true_positives").get<int>() + b.at("false_negatives").get<int>(), 28);
  for (const Json& demo : d.at("demos")) {
    const Json& segs = demo.at("segments");
    ASSERT_EQ(segs.size(), 8u) << demo;
    const double share = demo.at("steps").get<double>() / 8.0;
    for (std::size_t k = 0; k < segs.size(); ++k) {
      EXPECT_EQ(segs[k].at(0).get<int>(), static_cast<int>(k)) << demo;  // skill id = segment index
      EXPECT_NEAR(segs[k].at(2).get<int>() - segs[k].at(1).get<int>(), share, 1.0) << demo;
    }
  }
}

TEST(EvaluateSkillsCommand, PlantedWeaknessesNameTheExpertiseModeAndTheModeNeedsThem) {
  const auto r = run_skillcoach(
      "evaluate-skills --task writing --time-heuristic --planted-weaknesses --learners 1 --expertise quality-aware");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 learners per letter, seed 1, quality-aware expertise:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("| e |"), std::string::npos) << r.output;
  const auto alone = run_skillcoach("evaluate-skills --task writing --time-heuristic --expertise quality-aware");
  EXPECT_EQ(alone.exit_code, 2) << alone.output;
  EXPECT_EQ(test::count_lines(alone.output), 1) << alone.output;
}

// --readout-phases reads the model at other phases than its file's; the file's own number gives the same report.
TEST(EvaluateSkillsCommand, ReadoutPhasesReplaceTheFilesOnlyForTheRun) {
  const std::string model = test::tiny_model("writing").string();
  const std::string run = "evaluate-skills --task writing --count 6 --details --model " + model;
  const auto file = run_skillcoach(run);
  const auto three = run_skillcoach(run + " --readout-phases 3");
  const auto one = run_skillcoach(run + " --readout-phases 1");
  ASSERT_EQ(file.exit_code, 0) << file.output;
  ASSERT_EQ(three.exit_code, 0) << three.output;
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_EQ(report_json_of(three.output).at("demos"), report_json_of(file.output).at("demos"));
  EXPECT_NE(report_json_of(one.output).at("demos"), report_json_of(file.output).at("demos"));
  const auto heuristic = run_skillcoach("evaluate-skills --task writing --time-heuristic --readout-phases 3");
  EXPECT_EQ(heuristic.exit_code, 2) << heuristic.output;
  EXPECT_EQ(test::count_lines(heuristic.output), 1) << heuristic.output;
}

TEST(EvaluateSkillsCommand, NeedsAModelOrTheTimeHeuristic) {
  const auto r = run_skillcoach("evaluate-skills --task writing --count 2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("give a model (--model FILE) or --time-heuristic"), std::string::npos) << r.output;
  EXPECT_EQ(test::count_lines(r.output), 1) << r.output;
}

}  // namespace
}  // namespace sc
