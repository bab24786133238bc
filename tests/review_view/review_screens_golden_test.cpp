// Golden screenshots of the Review mode's session browser, trial viewer and expertise page, rendered by the real
// program offscreen (`skillcoach screenshot`): the trainer's deterministic screenshot session (fixed seed, timestamps
// and scripted learner) is the database they show.
#include <gtest/gtest.h>

#include <string>

#include "engine/render/rgba_image.hpp"
#include "tests/support/golden_image.hpp"
#include "tests/support/run_skillcoach.hpp"

namespace sc::test {
namespace {

class ReviewScreenGolden : public ::testing::TestWithParam<const char*> {};

TEST_P(ReviewScreenGolden, MatchesGolden) {
  const std::string screen = GetParam();
  const auto out = test_output_dir() / (screen + ".png");
  const CommandResult shot =
      run_skillcoach("screenshot --screen " + screen + " --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "review/screen_" + screen));
}

INSTANTIATE_TEST_SUITE_P(Review, ReviewScreenGolden, ::testing::Values("review", "review_trial", "review_expertise"));

// A writing learner in unseen drawer 13's letters: "diagnosis explained" names the hand it was also scored against
// and pictures its first pre-test word over the guide and over that hand.
TEST(ReviewScreenGolden, TheDiagnosisOfAWritingLearnerInAHandOfItsOwnPicturesTheHand) {
  const auto out = test_output_dir() / "review_expertise_writing_hand13.png";
  const CommandResult shot = run_skillcoach(
      "screenshot --screen review_expertise --task writing --learner-hand 13 "
      "--size 1280x720 --out '" +
      out.string() + "'");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  EXPECT_TRUE(matches_golden(read_png(out), "review/screen_review_expertise_writing_hand13"));
}

}  // namespace
}  // namespace sc::test
