// `skillcoach replay --task parking` through the built binary ($SKILLCOACH_BINARY).
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

struct CommandRun {
  std::string out;
  int exit_code = -1;
};

CommandRun run_skillcoach(const std::string& args) {
  const char* binary = std::getenv("SKILLCOACH_BINARY");
  CommandRun r;
  if (!binary || !std::filesystem::exists(binary)) return r;
  FILE* pipe = popen((std::string(binary) + " " + args + " 2>&1").c_str(), "r");
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) r.out += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string data(const char* name) { return std::string(std::getenv("SKILLCOACH_TEST_DATA")) + "/parking/data/" + name; }

bool binary_available() {
  const char* binary = std::getenv("SKILLCOACH_BINARY");
  return binary && std::filesystem::exists(binary);
}

TEST(ReplayCommand, PrintsOneLinePerStepAndASummary) {
  if (!binary_available()) GTEST_SKIP() << "skillcoach binary not built";
  const CommandRun r = run_skillcoach("replay --task parking " + data("expert_trial.json"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  int lines = 0;
  for (char c : r.out) lines += c == '\n';
  EXPECT_EQ(lines, 13);
  EXPECT_EQ(r.out.rfind("{\"t\":1,\"x\":", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("{\"t\":12,"), std::string::npos);
  EXPECT_NE(r.out.find("\"success\":true}\n{\"summary\":true,\"steps\":12,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"success_step\":12,\"collision\":false,\"ignored_actions\":0}"), std::string::npos) << r.out;
}

TEST(ReplayCommand, MalformedFileAndOtherTasksAreOneLineErrors) {
  if (!binary_available()) GTEST_SKIP() << "skillcoach binary not built";
  CommandRun r = run_skillcoach("replay --task parking " + data("bad_action.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "skillcoach: error: " + data("bad_action.json") + ": $.actions[1]: expected an array of 2 numbers [u0, u1]\n");
  r = run_skillcoach("replay --task cooking " + data("expert_trial.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "skillcoach: error: --task: replay supports \"parking\" only for now (got \"cooking\")\n");
}

}  // namespace
