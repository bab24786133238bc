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

TEST(LearnScreenGolden, WritingTrialMatchesGolden) {
  // A drill practice half-way: the ghost ribbon of the stitched drill, the scripted learner's ink over it.
  const auto out = test_output_dir() / "learn_trial_writing.png";
  const CommandResult shot =
      run_skillcoach("screenshot --screen learn_trial --task writing --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "learn/learn_trial_writing"));
}

TEST(LearnScreenGolden, WritingDiagnosisMatchesGolden) {
  // The writing pre-test's diagnosis (quality-aware expertise): letters and connectors with their pictures.
  const auto out = test_output_dir() / "learn_diagnosis_writing.png";
  const CommandResult shot =
      run_skillcoach("screenshot --screen learn_diagnosis --task writing --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "learn/learn_diagnosis_writing"));
}

INSTANTIATE_TEST_SUITE_P(Trainer, LearnScreenGolden,
                         ::testing::Values("learn_welcome", "learn_instructions", "learn_trial", "learn_diagnosis",
                                           "learn_summary"));

}  // namespace
}  // namespace sc::test
