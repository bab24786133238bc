// Golden screenshots of every screen of the trainer's flow (parking, and the writing trial screen; deterministic:
// fixed seed, scripted learner, fixed timestamps, fresh temporary database), rendered by the real program
// offscreen.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <ostream>
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

// The writing trainer's screens: `screen` of the writing session, golden learn/<screen>_writing; with a
// learner writing in Omniglot drawer `hand`'s letters, learn/<screen>_writing_hand<hand>.
struct WritingScreen {
  const char* screen;
  int hand;  // the scripted learner's hand (screenshot --learner-hand); 0: the guide's shapes
};

void PrintTo(const WritingScreen& s, std::ostream* out) { *out << s.screen << ", hand " << s.hand; }

class WritingLearnScreenGolden : public ::testing::TestWithParam<WritingScreen> {};

TEST_P(WritingLearnScreenGolden, MatchesGolden) {
  const WritingScreen param = GetParam();
  const std::string name =
      std::string(param.screen) + "_writing" + (param.hand > 0 ? "_hand" + std::to_string(param.hand) : std::string());
  const auto out = test_output_dir() / (name + ".png");
  const CommandResult shot =
      run_skillcoach(std::string("screenshot --screen ") + param.screen + " --task writing --learner-hand " +
                     std::to_string(param.hand) + " --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "learn/" + name));
}

// learn_trial: a drill practice half-way, the ghost ribbon of the stitched drill and the scripted learner's ink
// over it; learn_diagnosis: the pre-test's diagnosis (quality-aware expertise), letters and connectors pictured;
// in drawer 13's hand (one the references do not hold): the hand taken, its line and pictures.
INSTANTIATE_TEST_SUITE_P(Writing, WritingLearnScreenGolden,
                         ::testing::Values(WritingScreen{"learn_trial", 0}, WritingScreen{"learn_diagnosis", 0},
                                           WritingScreen{"learn_diagnosis", 13}),
                         [](const ::testing::TestParamInfo<WritingScreen>& info) {
                           return std::string(info.param.screen) + "_hand" + std::to_string(info.param.hand);
                         });

// Pointing at a small picture of the diagnosis page shows it four times as large with a caption: the place a
// parking target went wrong (row 1's right picture), and a writing learner's `b` in drawer 13's hand.
struct ZoomShot {
  const char* name;
  const char* options;  // screenshot options beyond --screen, --size and --out
};

void PrintTo(const ZoomShot& z, std::ostream* out) { *out << z.name; }

class LearnDiagnosisZoomGolden : public ::testing::TestWithParam<ZoomShot> {};

TEST_P(LearnDiagnosisZoomGolden, MatchesGolden) {
  const ZoomShot param = GetParam();
  const auto out = test_output_dir() / (std::string(param.name) + ".png");
  const CommandResult shot = run_skillcoach(std::string("screenshot --screen learn_diagnosis --size 1280x720 ") +
                                            param.options + " --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), std::string("learn/") + param.name));
}

// 10 frames: the page's auto-sized card settles, then the tooltip window takes a frame to size itself.
INSTANTIATE_TEST_SUITE_P(Trainer, LearnDiagnosisZoomGolden,
                         ::testing::Values(ZoomShot{"learn_diagnosis_zoom_place", "--mouse 393,205 --frames 10"},
                                           ZoomShot{"learn_diagnosis_writing_hand13_zoom_place",
                                                    "--task writing --learner-hand 13 --mouse 393,350 --frames 10"}),
                         [](const ::testing::TestParamInfo<ZoomShot>& info) {
                           return info.index == 0 ? std::string("parking") : std::string("writing_hand13");
                         });

INSTANTIATE_TEST_SUITE_P(Trainer, LearnScreenGolden,
                         ::testing::Values("learn_welcome", "learn_instructions", "learn_trial", "learn_diagnosis",
                                           "learn_summary"));

}  // namespace
}  // namespace sc::test
