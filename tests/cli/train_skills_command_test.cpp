// `skillcoach train-skills` end to end (tiny runs: a few demonstrations, one or two iterations).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "teaching/skills/restart_choice.hpp"
#include "tests/cli/skills_cli_fixture.hpp"

namespace sc {
namespace {

using test::run_skillcoach;
using test::scratch_path;

TEST(TrainSkillsCommand, SameSeedGivesTheSameModelBytesAndAnotherSeedDoesNot) {
  const auto a = scratch_path("train_skills", "a.pt"), b = scratch_path("train_skills", "b.pt"),
             c = scratch_path("train_skills", "c.pt");
  const std::string common =
      "train-skills --task writing --demos 6 --iterations 2 --noise-floor-learners 0 --restart-choice nll ";
  ASSERT_EQ(run_skillcoach(common + "--seed 5 --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run_skillcoach(common + "--seed 5 --out " + b.string()).exit_code, 0);
  ASSERT_EQ(run_skillcoach(common + "--seed 6 --out " + c.string()).exit_code, 0);
  EXPECT_EQ(test::read_bytes(a), test::read_bytes(b));
  EXPECT_NE(test::read_bytes(a), test::read_bytes(c));
  EXPECT_FALSE(read_json_file(a.string() + ".json").at("metrics").contains("restart_score"));
  EXPECT_FALSE(std::filesystem::exists(a.string() + ".restart0.pt"));
}

// Generated writing words keep, by default, the restart choose_restart picks with the cross-hand check's kappa,
// recorded with how it was measured; --save-every-restart writes each run's model, the kept one byte for byte.
TEST(TrainSkillsCommand, WritingKeepsTheRestartMostConsistentWithOtherHands) {
  const auto model = scratch_path("train_skills", "cross_hand.pt");
  const auto r = run_skillcoach(
      "train-skills --task writing --demos 6 --iterations 2 --noise-floor-learners 0 --seed 0 --save-every-restart "
      "--restart-check-words 20 --out " +
      model.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json metrics = read_json_file(model.string() + ".json").at("metrics");
  std::vector<RestartOutcome> outcomes;
  for (int k = 0; k < 2; ++k) {
    const double score = metrics.at("restart_score").at(k).get<double>();
    EXPECT_TRUE(score >= -1.0 && score <= 1.0) << metrics;
    outcomes.push_back({metrics.at("restart_valid_nll").at(k).get<double>(), NAN, score});
  }
  const int kept = metrics.at("restart").get<int>();
  EXPECT_EQ(kept, static_cast<int>(choose_restart(outcomes))) << metrics;
  EXPECT_NE(metrics.at("restart_score_kind").get<std::string>().find("drawers 1-10, 20 classic words"),
            std::string::npos);
  const std::string restart = model.string() + ".restart";
  EXPECT_EQ(test::read_bytes(restart + std::to_string(kept) + ".pt"), test::read_bytes(model));
  EXPECT_NE(test::read_bytes(restart + std::to_string(1 - kept) + ".pt"), test::read_bytes(model));
}

TEST(TrainSkillsCommand, RestartChoiceByOtherHandsIsOnlyForWriting) {
  const auto r =
      run_skillcoach("train-skills --task parking --demos 5 --iterations 1 --restart-choice cross-hand --out " +
                     scratch_path("train_skills", "cross_parking.pt").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("only for writing"), std::string::npos) << r.output;
}

TEST(TrainSkillsCommand, SidecarRecordsConfigDataSeedMetricsAndRevision) {
  const auto model = scratch_path("train_skills", "sidecar.pt");
  const auto r =
      run_skillcoach("train-skills --task parking --demos 5 --iterations 2 --seed 7 --out " + model.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json s = read_json_file(model.string() + ".json");
  EXPECT_EQ(s.at("task"), "parking");
  EXPECT_EQ(s.at("seed"), 7);
  EXPECT_EQ(s.at("config").at("mode"), "statediff+action");  // the paper's parking defaults
  EXPECT_EQ(s.at("config").at("latent_size"), 16);
  EXPECT_NE(s.at("data").get<std::string>().find("random classic scenarios"), std::string::npos) << s.at("data");
  EXPECT_EQ(s.at("metrics").at("iterations_run"), 2);
  EXPECT_TRUE(s.at("metrics").at("valid_action_reconstruction_error").is_number());
  EXPECT_TRUE(s.at("git_revision").is_string());
}

// A config field that the sidecar writes only when it is off (encoder_reads_actions) is still a --set key;
// an action-only mode cannot take it.
TEST(TrainSkillsCommand, SetReachesFieldsWrittenOnlyWhenOff) {
  const auto model = scratch_path("train_skills", "states_only.pt");
  const std::string common = "train-skills --demos 5 --iterations 1 --seed 7 --set encoder_reads_actions=false ";
  const auto r = run_skillcoach(common + "--task parking --out " + model.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_json_file(model.string() + ".json").at("config").at("encoder_reads_actions"), false);
  const auto writing = run_skillcoach(common + "--task writing --noise-floor-learners 0 --out " +
                                      scratch_path("train_skills", "no_states.pt").string());
  EXPECT_EQ(writing.exit_code, 2) << writing.output;
  EXPECT_NE(writing.output.find("encoder_reads_actions=false needs a mode with states"), std::string::npos)
      << writing.output;
}

TEST(TrainSkillsCommand, ProgressIsPlainLinesWhenStderrIsNotATerminal) {
  const auto model = scratch_path("train_skills", "progress.pt");
  const auto r = run_skillcoach(
      "train-skills --task writing --demos 6 --iterations 3 --seed 1 --noise-floor-learners 0 --restart-choice nll "
      "--out " +
      model.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find('\r'), std::string::npos);
  EXPECT_NE(r.output.find("it 1/3  loss"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("it 3/3  loss"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("valid "), std::string::npos) << r.output;
}

TEST(TrainSkillsCommand, TrainsOnAFolderOfTrialFiles) {
  const auto dir = scratch_path("train_skills", "data");
  std::filesystem::create_directories(dir);
  for (int i = 0; i < 3; ++i)
    std::filesystem::copy_file(test::wavy_writing_trial("wavy.json"), dir / ("trial" + std::to_string(i) + ".json"),
                               std::filesystem::copy_options::overwrite_existing);
  const auto model = scratch_path("train_skills", "from_data.pt");
  const auto r = run_skillcoach("train-skills --task writing --data " + dir.string() +
                                " --iterations 1 --noise-floor-learners 2 --out " + model.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // A writing model records the noise floor it was calibrated to (here on 2 learners), where the kit reads it.
  const Json floor = read_json_file(model.string() + ".json").at("execution_noise_floor");
  EXPECT_TRUE(floor.at("value").is_number()) << floor;
  EXPECT_EQ(floor.at("learners"), 2);
  EXPECT_NE(r.output.find("noise floor"), std::string::npos) << r.output;
  EXPECT_NE(read_json_file(model.string() + ".json").at("data").get<std::string>().find("3 writing trial files"),
            std::string::npos);
}

TEST(TrainSkillsCommand, BadTrialFileIsOneErrorLineAndExitTwo) {
  const auto dir = scratch_path("train_skills", "bad_data");
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(test::wavy_writing_trial("wavy2.json"), dir / "good.json",
                             std::filesystem::copy_options::overwrite_existing);
  test::write_bytes(dir / "broken.json", "{\"task\": \"writing\", \"points\": [[0, 1], [2");
  const auto r = run_skillcoach("train-skills --task writing --data " + dir.string() + " --out " +
                                scratch_path("train_skills", "never.pt").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("skillcoach: error: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("broken.json"), std::string::npos) << r.output;
  EXPECT_EQ(test::count_lines(r.output.substr(r.output.find("skillcoach: error: "))), 1) << r.output;
  EXPECT_FALSE(std::filesystem::exists(scratch_path("train_skills", "never.pt")));
}

TEST(TrainSkillsCommand, ParkingTrialInAWritingFolderIsRefused) {
  const auto dir = scratch_path("train_skills", "mixed");
  std::filesystem::create_directories(dir);
  write_json_file(dir / "parking.json", Json{{"task", "parking"}});
  const auto r = run_skillcoach("train-skills --task writing --data " + dir.string() + " --out " +
                                scratch_path("train_skills", "never2.pt").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("parking.json: not a writing trial"), std::string::npos) << r.output;
}

TEST(TrainSkillsCommand, FixedBoundariesMarkTheModelAsADiagnostic) {
  const auto model = scratch_path("train_skills", "fixed.pt");
  const auto r =
      run_skillcoach("train-skills --task writing --demos 6 --iterations 2 --fix-boundaries --out " + model.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json s = read_json_file(model.string() + ".json");
  EXPECT_EQ(s.at("metrics").at("fixed_boundaries"), true);
  EXPECT_TRUE(s.at("metrics").at("valid_action_reconstruction_error").is_null());
  EXPECT_TRUE(s.at("metrics").at("best_valid_nll").is_number());
  EXPECT_NE(s.at("data").get<std::string>().find("DIAGNOSTIC: boundaries fixed"), std::string::npos) << s.at("data");
}

TEST(TrainSkillsCommand, FixedBoundariesNeedKnownBoundaries) {
  const auto r = run_skillcoach("train-skills --task parking --demos 5 --iterations 1 --fix-boundaries --out " +
                                scratch_path("train_skills", "never3.pt").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--fix-boundaries: demonstration"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("has no known boundaries"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(scratch_path("train_skills", "never3.pt")));
}

}  // namespace
}  // namespace sc
