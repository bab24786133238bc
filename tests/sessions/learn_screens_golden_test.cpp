// Golden screenshots of every screen of the trainer's flow (parking, and the writing trial screen; deterministic:
// fixed seed, scripted learner, fixed timestamps, fresh temporary database), rendered by the real program
// offscreen.
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
  const CommandResult shot =
      run_skillcoach(std::string("screenshot --screen ") + screen + " --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "learn/" + screen));
}

// The writing trainer's screens: `screen` of the writing session, golden learn/<screen>_writing.
class WritingLearnScreenGolden : public ::testing::TestWithParam<const char*> {};

TEST_P(WritingLearnScreenGolden, MatchesGolden) {
  const std::string screen = GetParam();
  const auto out = test_output_dir() / (screen + "_writing.png");
  const CommandResult shot =
      run_skillcoach("screenshot --screen " + screen + " --task writing --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "learn/" + screen + "_writing"));
}

// learn_trial: a drill practice half-way, the ghost ribbon of the stitched drill and the scripted learner's ink
// over it; learn_diagnosis: the pre-test's diagnosis (quality-aware expertise), letters and connectors pictured.
INSTANTIATE_TEST_SUITE_P(Writing, WritingLearnScreenGolden, ::testing::Values("learn_trial", "learn_diagnosis"));

INSTANTIATE_TEST_SUITE_P(Trainer, LearnScreenGolden,
                         ::testing::Values("learn_welcome", "learn_instructions", "learn_trial", "learn_diagnosis",
                                           "learn_summary"));

}  // namespace
}  // namespace sc::test
