// `skillcoach replay --task parking` through the built binary ($SKILLCOACH_BINARY).
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include "tests/support/run_skillcoach.hpp"

namespace {

std::string data(const char* name) {
  return std::string(std::getenv("SKILLCOACH_TEST_DATA")) + "/parking/data/" + name;
}

TEST(ReplayCommand, PrintsOneLinePerStepAndASummary) {
  const sc::test::CommandResult r = sc::test::run_skillcoach("replay --task parking " + data("expert_trial.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int lines = 0;
  for (char c : r.output) lines += c == '\n';
  EXPECT_EQ(lines, 13);
  EXPECT_EQ(r.output.rfind("{\"t\":1,\"x\":", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("{\"t\":12,"), std::string::npos);
  EXPECT_NE(r.output.find("\"success\":true}\n{\"summary\":true,\"steps\":12,"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"success_step\":12,\"collision\":false,\"ignored_actions\":0}"), std::string::npos)
      << r.output;
}

TEST(ReplayCommand, MalformedFileAndOtherTasksAreOneLineErrors) {
  sc::test::CommandResult r = sc::test::run_skillcoach("replay --task parking " + data("bad_action.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output, "skillcoach: error: " + data("bad_action.json") +
                          ": $.actions[1]: expected an array of 2 numbers [u0, u1]\n");
  r = sc::test::run_skillcoach("replay --task cooking " + data("expert_trial.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--task: cooking not in {parking,writing}"), std::string::npos) << r.output;
  r = sc::test::run_skillcoach("replay --task writing " + data("expert_trial.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output,
            "skillcoach: error: --task: replay simulates parking trials only (a writing trial has nothing to "
            "re-simulate)\n");
}

}  // namespace
