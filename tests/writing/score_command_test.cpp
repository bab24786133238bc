// `skillcoach score --task writing FILE.json` end to end (app/cli/score_command.cpp).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "engine/core/json_file.hpp"
#include "engine/writing/writing_trial.hpp"
#include "tests/support/run_skillcoach.hpp"

namespace sc::writing {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const char* out = std::getenv("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::path dir = std::filesystem::path(out ? out : "/tmp") / "writing_cli";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(ScoreCommand, GoldTrialScoresZeroAndHalfAWordAboutHalf) {
  const WritingScenario scenario{"b-a-t-", AlphabetKind::Classic, {}};
  auto trial = gold_trial(scenario);
  const auto gold_file = scratch("gold.json");
  write_writing_trial(gold_file, trial);
  const test::CommandResult gold = test::run_skillcoach("score --task writing " + gold_file.string());
  ASSERT_EQ(gold.exit_code, 0) << gold.output;
  const Json doc = parse_json_text(gold.output, "stdout");
  EXPECT_EQ(doc["score"].get<double>(), 0.0);
  EXPECT_EQ(doc["recall"].get<double>(), 1.0);
  EXPECT_EQ(doc["scenario"]["word"], "b-a-t-");

  trial.points.resize(trial.points.size() / 2);
  trial.times.resize(trial.points.size());
  trial.score = -0.5;
  const auto half_file = scratch("half.json");
  write_writing_trial(half_file, trial);
  const test::CommandResult half = test::run_skillcoach("score --task writing " + half_file.string());
  ASSERT_EQ(half.exit_code, 0) << half.output;
  const Json h = parse_json_text(half.output, "stdout");
  EXPECT_NEAR(h["score"].get<double>(), -0.5, 0.1);
  EXPECT_EQ(h["precision"].get<double>(), 1.0);
  EXPECT_EQ(h["stored_score"].get<double>(), -0.5);
}

TEST(ScoreCommand, BadInputExitsTwoWithOneLine) {
  const auto bad = scratch("bad.json");
  std::ofstream(bad) << R"({"task": "writing", "scenario": {"word": "ab"}, "points": [[1, "x"]]})";
  const test::CommandResult r = test::run_skillcoach("score --task writing " + bad.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output, "skillcoach: error: " + bad.string() + ": $.points[0][1]: expected a number, got string\n");
}

}  // namespace
}  // namespace sc::writing
