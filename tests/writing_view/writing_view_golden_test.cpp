// Golden images of the writing canvas (offscreen, GALLIUM_DRIVER=llvmpipe pinned by the test environment):
// a classic word, a multi-stroke full-alphabet word with the ghost pen, learner ink over the guide with its
// score, the expert's ghost overlay on a trial, and a drill ribbon. Regenerate with
//   SKILLCOACH_UPDATE_GOLDENS=1 ctest -R WritingViewGolden   (then look at every PNG before committing).
#include <gtest/gtest.h>

#include "engine/writing/writing_trial.hpp"
#include "engine/writing_view/canvas_geometry.hpp"
#include "engine/writing_view/scripted_trace.hpp"
#include "engine/writing_view/writing_trial_image.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::writing_view {
namespace {

using writing::AlphabetKind;
using writing::WritingScenario;

constexpr int kWidth = 800;
constexpr int kHeight = 480;

WritingRenderOptions golden_options() {
  WritingRenderOptions options;
  options.width = kWidth;
  options.height = kHeight;
  return options;
}

// A multi-stroke word of the full alphabet: P (character16) and T (character20) have two strokes after
// drawer 1, I (character09) has four after drawer 6.
WritingScenario multi_stroke_scenario() { return {"P-I^T", AlphabetKind::Balinese, {{'I', 6}}}; }

writing::WritingTrial scripted_trial(const WritingScenario& scenario, const ScriptedHand& hand) {
  writing::WritingTrial trial;
  trial.scenario = scenario;
  trial.points = scripted_learner_trace(writing::gold_trajectory(scenario).points(), hand);
  trial.source = "learner";
  trial.device = "mouse";
  return trial;
}

TEST(WritingViewGolden, ClassicExpertWord) {
  const auto trial = writing::gold_trial({"b-a-t-^-", AlphabetKind::Classic, {}});
  EXPECT_TRUE(test::matches_golden(render_writing_trial_image(trial, golden_options()), "writing/classic_expert"));
}

TEST(WritingViewGolden, MultiStrokeWordWithGhostPen) {
  const WritingScenario scenario = multi_stroke_scenario();
  const auto gold = writing::gold_trajectory(scenario).points();
  WritingScene scene;
  scene.guide = gold;
  // Far enough that the pen has lifted between strokes of I several times (dashed hops behind it).
  scene.ghost_pen = ghost_pen_at(gold, 0.62 * ghost_pen_duration(gold.size()));
  scene.caption = "P-I^T  \xc2\xb7  balinese  \xc2\xb7  ghost pen";
  EXPECT_TRUE(test::matches_golden(render_writing_scene_image(scene, kWidth, kHeight), "writing/balinese_ghost_pen"));
}

TEST(WritingViewGolden, LearnerInkOverGuideWithScore) {
  const auto trial = scripted_trial({"ab-c", AlphabetKind::Classic, {}}, {7, 3.0, 4, 0.8});
  EXPECT_TRUE(test::matches_golden(render_writing_trial_image(trial, golden_options()), "writing/learner_over_guide"));
}

TEST(WritingViewGolden, ExpertGhostOverlayOnATrial) {
  auto options = golden_options();
  options.overlay_expert = true;
  const auto trial = scripted_trial(multi_stroke_scenario(), {11, 4.0, 4, 1.0});
  EXPECT_TRUE(test::matches_golden(render_writing_trial_image(trial, options), "writing/ghost_overlay"));
}

TEST(WritingViewGolden, DrillRibbonWithStartDotAndArrows) {
  // A drill = a piece of the gold word (here the character I with its pen-up moves), drawn where it sits.
  const WritingScenario scenario = multi_stroke_scenario();
  const writing::WordTrajectory gold = writing::gold_trajectory(scenario);
  const auto points = gold.points();
  const auto begin = static_cast<std::size_t>(gold.character_starts[2]);
  const auto end = static_cast<std::size_t>(gold.character_starts[3]);
  WritingScene scene;
  scene.guide = points;
  scene.ribbon.assign(points.begin() + static_cast<std::ptrdiff_t>(begin),
                      points.begin() + static_cast<std::ptrdiff_t>(end) + 1);
  scene.caption = "drill: I";
  EXPECT_TRUE(test::matches_golden(render_writing_scene_image(scene, kWidth, kHeight), "writing/drill_ribbon"));
}

}  // namespace
}  // namespace sc::writing_view
