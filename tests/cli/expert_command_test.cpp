// `skillcoach expert --task writing` end to end: gold trial files of generated words, usable as data.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/core/json_file.hpp"
#include "tests/cli/skills_cli_fixture.hpp"

namespace sc {
namespace {

using test::run_skillcoach;

TEST(ExpertCommand, WritingWritesGoldTrialsOfTheWordsTrainSkillsGenerates) {
  const std::filesystem::path dir = test::fresh_scratch_dir("expert_writing");
  const auto r = run_skillcoach("expert --task writing --count 3 --seed 1 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("3 classic words (seed 1)"), std::string::npos) << r.output;
  // evaluate-skills --seed 1 generates the same words in the same order (docs/skills.md lists them).
  const char* expected[] = {"b-a-t---", "^-c-a-t-", "t-e-a-c-"};
  for (int i = 0; i < 3; ++i) {
    const std::filesystem::path file = dir / ("expert_0000" + std::to_string(i) + ".json");
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const Json trial = read_json_file(file);
    EXPECT_EQ(trial.at("task"), "writing");
    EXPECT_EQ(trial.at("source"), "expert");
    EXPECT_EQ(trial.at("scenario").at("word"), expected[i]);
    EXPECT_GT(trial.at("points").size(), 1000u);  // an 8-symbol word is ~1250-2700 pen points
    EXPECT_EQ(trial.at("t").size(), trial.at("points").size());
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "expert_00003.json"));
  // The files are trials the other commands read.
  const auto seg = run_skillcoach("segment --task writing " + (dir / "expert_00000.json").string());
  EXPECT_EQ(seg.exit_code, 0) << seg.output;
}

TEST(ExpertCommand, WritingNeedsAnOutputFolderAndRefusesParkingOptions) {
  const auto no_out = run_skillcoach("expert --task writing --count 2");
  EXPECT_EQ(no_out.exit_code, 2) << no_out.output;
  EXPECT_NE(no_out.output.find("--out"), std::string::npos) << no_out.output;
  const auto parking_only = run_skillcoach("expert --task writing --variant parked --out " +
                                           test::fresh_scratch_dir("expert_writing_bad").string());
  EXPECT_EQ(parking_only.exit_code, 2) << parking_only.output;
  EXPECT_EQ(test::count_lines(parking_only.output), 1) << parking_only.output;
  const auto juggling = run_skillcoach("expert --task juggling");
  EXPECT_EQ(juggling.exit_code, 2) << juggling.output;  // CLI11 refuses it (not parking or writing)
}

}  // namespace
}  // namespace sc
