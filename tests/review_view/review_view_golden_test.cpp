// Golden images of the instructor review's three pictures, from the fixed learner database of
// tests/review/review_fixture.cpp: the trial viewer (a pre-test trial over the expert's path, skill
// segments, boundaries, reward plot), the before/after overlay of a scenario family, and the per-skill
// expertise-across-rounds chart. The data->picture glue is the app's (app/gui/screens/review_pictures.cpp),
// compiled into this test so the goldens show exactly what `skillcoach report` and the Review screens draw.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/core/review_pictures.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/review_view/review_palette.hpp"
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

  // The session's colours, as the Review and the report take them.
  static review_view::SkillPalette palette() {
    return session_palette(review::expertise_rounds(review_->kit(), review_->record()));
  }

  static std::unique_ptr<review::SessionReview> review_;
  std::unique_ptr<GlContext> context_ = create_offscreen_context_from_env(kWidth, kHeight);
};
std::unique_ptr<review::SessionReview> ReviewPictures::review_;

TEST_F(ReviewPictures, TrialViewerMatchesGolden) {
  // The cut-short second pre-test trial would show little; the first shows a whole attempt.
  const int seq = review_->record().trials_of(records::TrialKind::Pretest).front()->seq;
  const review::TrialReview trial = review_->trial(seq);
  const RgbaImage image = review_view::render_trial_image(*context_, trial_picture(trial, palette()),
                                                          trial_image_text("Ada", trial), kWidth, kHeight);
  EXPECT_TRUE(test::matches_golden(image, "review/trial_viewer"));
}

TEST_F(ReviewPictures, PracticeTrialWithGhostMatchesGolden) {
  const int seq = review_->record().trials_of(records::TrialKind::Practice).front()->seq;
  const review::TrialReview trial = review_->trial(seq);
  const RgbaImage image = review_view::render_trial_image(*context_, trial_picture(trial, palette()),
                                                          trial_image_text("Ada", trial), kWidth, kHeight);
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

// The session's skills take the palette's hues in turn: no two of its chart's skills share a colour (by skill id
// alone, skills 6 and 14 of this session were both yellow).
TEST_F(ReviewPictures, NoTwoSkillsOfTheSessionShareAColour) {
  const review::ExpertiseRounds rounds = review::expertise_rounds(review_->kit(), review_->record());
  const review_view::ExpertiseChart chart = expertise_chart(rounds, session_palette(rounds));
  ASSERT_GE(chart.skills.size(), 2u);
  ASSERT_LE(chart.skills.size(), 8u);
  std::set<ImU32> colours;
  for (const auto& s : chart.skills) colours.insert(chart.palette.color_u32(s.skill));
  EXPECT_EQ(colours.size(), chart.skills.size());
}

TEST_F(ReviewPictures, ExpertiseChartMatchesGolden) {
  const review::ExpertiseRounds rounds = review::expertise_rounds(review_->kit(), review_->record());
  const RgbaImage image = review_view::render_expertise_chart_image(
      *context_, expertise_chart(rounds, session_palette(rounds)), "Expertise per skill across rounds", kWidth);
  EXPECT_TRUE(test::matches_golden(image, "review/expertise_chart"));
}

// A chart of many skills and rounds grows its image and keeps its text at the 720-line size: every skill is in the
// picture (before, the text grew with the height, and a 4-round parking chart lost its last skills off the bottom).
TEST_F(ReviewPictures, AChartOfManySkillsAndRoundsKeepsEverySkillInItsImage) {
  review_view::ExpertiseChart chart;
  for (int r = 0; r < 6; ++r) chart.rounds.push_back("round " + std::to_string(r + 1));
  for (int m = 0; m < 16; ++m)
    chart.skills.push_back({m, "skill words " + std::to_string(m), std::vector<std::optional<double>>(6, -0.1 * m),
                            std::vector<bool>(6, m % 2 == 0)});
  chart.lowest = -1.5;
  const RgbaImage image = review_view::render_expertise_chart_image(*context_, chart, "Many skills", kWidth);
  EXPECT_GT(image.height, 2 * kHeight);
  // The last skill's bars are drawn in its colour (its last round the brightest, opaque): find them in the
  // bottom tenth of the image, and nothing but the background in its last rows.
  const ImU32 last = chart.palette.color_u32(15);
  const auto channel = [](ImU32 c, int shift) { return static_cast<int>((c >> shift) & 0xFF); };
  int found = 0;
  for (int y = image.height * 9 / 10; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      found += std::abs(p[0] - channel(last, 0)) <= 2 && std::abs(p[1] - channel(last, 8)) <= 2 &&
               std::abs(p[2] - channel(last, 16)) <= 2;
    }
  EXPECT_GT(found, 1000);
}

}  // namespace
}  // namespace sc
