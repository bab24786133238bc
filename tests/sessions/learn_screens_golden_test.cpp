// Golden screenshots of every screen of the trainer's flow (parking; deterministic: fixed seed, scripted
// learner, fixed timestamps, fresh temporary database), rendered by the real program offscreen.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/render/rgba_image.hpp"
#include "tests/support/golden_image.hpp"
#include "tests/support/run_skillcoach.hpp"

namespace sc::test {
namespace {

class LearnScreenGolden : public ::testing::TestWithParam<const char*> {};

TEST_P(LearnScreenGolden, MatchesGolden) {
  const std::string screen = GetParam();
  const auto out = test_output_dir() / (screen + ".png");
  const CommandResult shot = run_skillcoach(std::string("screenshot --screen ") + screen + " --size 1280x720 --out '" +
                                           out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "learn/" + screen));
}

INSTANTIATE_TEST_SUITE_P(Trainer, LearnScreenGolden,
                         ::testing::Values("learn_welcome", "learn_instructions", "learn_trial", "learn_diagnosis",
                                           "learn_summary"));

}  // namespace
}  // namespace sc::test
