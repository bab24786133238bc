// Golden screenshots of every screen of the trainer's flow (parking; deterministic: fixed seed, scripted
// learner, fixed timestamps, fresh temporary database), rendered by the real program offscreen.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/render/rgba_image.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::test {
namespace {

int screenshot(const std::string& screen, const std::filesystem::path& out) {
  const char* binary = std::getenv("SKILLCOACH_BINARY");
  const std::string command = std::string(binary ? binary : "skillcoach") + " screenshot --screen " + screen +
                              " --size 1280x720 --out '" + out.string() + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) std::fputs(buffer, stderr);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class LearnScreenGolden : public ::testing::TestWithParam<const char*> {};

TEST_P(LearnScreenGolden, MatchesGolden) {
  const std::string screen = GetParam();
  const auto out = test_output_dir() / (screen + ".png");
  ASSERT_EQ(screenshot(screen, out), 0);
  EXPECT_TRUE(matches_golden(read_png(out), "learn/" + screen));
}

INSTANTIATE_TEST_SUITE_P(Trainer, LearnScreenGolden,
                         ::testing::Values("learn_welcome", "learn_instructions", "learn_trial", "learn_diagnosis",
                                           "learn_summary"));

}  // namespace
}  // namespace sc::test
