// Golden images of the instructor review's three pictures, from the fixed learner database of
// tests/review/review_fixture.cpp: the trial viewer (a pre-test trial over the expert's path, skill
// segments, boundaries, reward plot), the before/after overlay of a scenario family, and the per-skill
// expertise-across-rounds chart. The data->picture glue is the app's (app/gui/screens/review_pictures.cpp),
// compiled into this test so the goldens show exactly what `skillcoach report` and the Review screens draw.
#include <gtest/gtest.h>

#include <memory>

#include "app/core/review_pictures.hpp"
#include "engine/render/gl_context.hpp"
#include "teaching/review/expertise_rounds.hpp"
#include "tests/review/review_fixture.hpp"
#include "tests/support/golden_image.hpp"

namespace sc {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;

class ReviewPictures : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto& f = test::parking_review_fixture();
    const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
    review_ =
        std::make_unique<review::SessionReview>(test::parking_kit(), review::load_session_record(store, f.session_id));
  }
  static void TearDownTestSuite() { review_.reset(); }

  static std::unique_ptr<review::SessionReview> review_;
  std::unique_ptr<GlContext> context_ = create_offscreen_context_from_env(kWidth, kHeight);
};
std::unique_ptr<review::SessionReview> ReviewPictures::review_;

TEST_F(ReviewPictures, TrialViewerMatchesGolden) {
  // The cut-short second pre-test trial would show little; the first shows a whole attempt.
  const int seq = review_->record().trials_of(records::TrialKind::Pretest).front()->seq;
  const review::TrialReview trial = review_->trial(seq);
  const RgbaImage image =
      review_view::render_trial_image(*context_, trial_picture(trial), trial_image_text("Ada", trial), kWidth, kHeight);
  EXPECT_TRUE(test::matches_golden(image, "review/trial_viewer"));
}

TEST_F(ReviewPictures, PracticeTrialWithGhostMatchesGolden) {
  const int seq = review_->record().trials_of(records::TrialKind::Practice).front()->seq;
  const review::TrialReview trial = review_->trial(seq);
  const RgbaImage image =
      review_view::render_trial_image(*context_, trial_picture(trial), trial_image_text("Ada", trial), kWidth, kHeight);
  EXPECT_TRUE(test::matches_golden(image, "review/trial_viewer_practice"));
}

TEST_F(ReviewPictures, BeforeAfterMatchesGolden) {
  std::vector<review::TrialReview> trials;
  for (const auto& t : review_->record().trials)
    if (t.record.kind == records::TrialKind::Pretest || t.record.kind == records::TrialKind::Eval)
      trials.push_back(review_->trial(t.seq));
  const auto groups = review::before_after_groups(review_->record());
  ASSERT_FALSE(groups.empty());
  // The family with the most trials makes the fullest picture.
  const auto& group = *std::max_element(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
    return a.pretest_seqs.size() + a.eval_seqs.size() < b.pretest_seqs.size() + b.eval_seqs.size();
  });
  const RgbaImage image = review_view::render_before_after_image(*context_, before_after_picture(group, trials),
                                                                 "Before / after: " + group.title,
                                                                 before_after_lines(group, trials), kWidth, kHeight);
  EXPECT_TRUE(test::matches_golden(image, "review/before_after"));
}

TEST_F(ReviewPictures, ExpertiseChartMatchesGolden) {
  const review::ExpertiseRounds rounds = review::expertise_rounds(review_->kit(), review_->record());
  const RgbaImage image = review_view::render_expertise_chart_image(*context_, expertise_chart(rounds),
                                                                    "Expertise per skill across rounds", kWidth);
  EXPECT_TRUE(test::matches_golden(image, "review/expertise_chart"));
}

}  // namespace
}  // namespace sc
