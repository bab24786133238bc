#include "engine/writing_view/canvas_pen_input.hpp"

#include <gtest/gtest.h>

#include "engine/writing_view/canvas_geometry.hpp"

namespace sc::writing_view {
namespace {

using writing::TrialEnd;

// 1048 x 648 pixels show the 524 x 324 canvas-with-margin at exactly 2 px per canvas pixel.
Camera2D camera() { return writing_canvas_camera({0, 0, 1048, 648}); }
// The framebuffer pixel of a canvas point.
Vec2f px(float x, float y) { return camera().world_to_pixel({x, y}); }

writing::PenRecorderRules classic_rules() { return {true, 20.0}; }
writing::PenRecorderRules multi_stroke_rules() { return {false, 20.0}; }

TEST(CanvasPenInput, ConvertsWindowPixelsToCanvasPixelsThroughTheCamera) {
  const writing::PenSample s = pen_sample_at(camera(), {1.5, {24.0f + 2.0f * 100.0f, 24.0f + 2.0f * 150.0f}, true});
  EXPECT_NEAR(s.x, 100.0, 1e-4);
  EXPECT_NEAR(s.y, 150.0, 1e-4);
  EXPECT_TRUE(s.pressed);
  EXPECT_DOUBLE_EQ(s.time, 1.5);
  EXPECT_TRUE(on_canvas(camera(), px(250, 150)));
  EXPECT_FALSE(on_canvas(camera(), px(-5, 150)));
  EXPECT_FALSE(on_canvas(camera(), px(250, 305)));
}

TEST(CanvasPenInput, PressDrawsMotionEventsAndFramesAreSampledReleaseEndsAClassicTrial) {
  CanvasPenInput pen(classic_rules());
  const Camera2D cam = camera();
  pen.feed({10.0, px(0, 150), false}, cam);  // hovering: not recorded, clock not started
  EXPECT_FALSE(pen.started());
  pen.feed({10.1, px(0, 150), true}, cam);  // button-down event
  EXPECT_TRUE(pen.drawing());
  pen.feed({10.11, px(3, 149), true}, cam);   // motion event
  pen.feed({10.12, px(6, 148), true}, cam);   // motion event
  pen.feed({10.13, px(6, 148), true}, cam);   // the frame's polled state: same place, not repeated
  pen.feed({10.15, px(9, 150), false}, cam);  // button-up event
  EXPECT_TRUE(pen.ended());
  EXPECT_EQ(pen.end_reason(), TrialEnd::Released);
  const writing::TimedTrace raw = pen.raw();
  ASSERT_EQ(raw.points.size(), 4u);
  EXPECT_FALSE(raw.points[0].pen);  // the pen arrived lifted
  EXPECT_TRUE(raw.points[3].pen);
  EXPECT_NEAR(raw.points[2].x, 6.0, 1e-4);
  EXPECT_NEAR(raw.points[2].y, 148.0, 1e-4);
  EXPECT_NEAR(raw.times[0], 0.0, 1e-12);  // relative to the first pen-down
  EXPECT_NEAR(raw.times[3], 0.05, 1e-9);
  // Infilled as the reference infilled its users' traces: steps of at most 1 px.
  const writing::TimedTrace filled = pen.infilled();
  for (std::size_t i = 1; i < filled.points.size(); ++i) {
    EXPECT_LE(std::abs(filled.points[i].x - filled.points[i - 1].x), 1.0 + 1e-9);
    EXPECT_LE(std::abs(filled.points[i].y - filled.points[i - 1].y), 1.0 + 1e-9);
  }
  pen.feed({10.2, px(20, 150), true}, cam);  // after the end nothing is recorded
  EXPECT_EQ(pen.raw().points.size(), 4u);
}

TEST(CanvasPenInput, PressesOffTheCanvasOrOnTheUiDoNotStartThePen) {
  CanvasPenInput pen(classic_rules());
  const Camera2D cam = camera();
  pen.feed({1.0, px(-8, 150), true}, cam);  // on the desk beside the paper
  pen.feed({1.1, px(-8, 150), false}, cam);
  pen.feed({1.2, px(50, 150), true}, cam, /*may_press=*/false);  // a click on a widget over the canvas
  pen.feed({1.3, px(50, 150), false}, cam, false);
  EXPECT_FALSE(pen.started());
  // Once down on the canvas, the pen follows the mouse off the paper until release.
  pen.feed({2.0, px(490, 150), true}, cam);
  pen.feed({2.1, px(520, 150), true}, cam, false);
  EXPECT_NEAR(pen.raw().points.back().x, 520.0, 1e-3);
}

TEST(CanvasPenInput, MultiStrokeWordsLiftThePenAndEndWithDone) {
  CanvasPenInput pen(multi_stroke_rules());
  const Camera2D cam = camera();
  pen.feed({0.0, px(10, 150), true}, cam);
  pen.feed({0.1, px(30, 150), true}, cam);
  pen.feed({0.2, px(30, 150), false}, cam);
  EXPECT_FALSE(pen.ended());  // a release is a pen lift, not the end
  pen.feed({0.3, px(40, 120), false}, cam);
  pen.feed({0.4, px(40, 120), true}, cam);
  pen.feed({0.5, px(40, 140), true}, cam);
  pen.feed({0.6, px(40, 140), false}, cam);
  pen.done(0.7);
  EXPECT_EQ(pen.end_reason(), TrialEnd::Done);
  const auto points = pen.raw().points;
  int lifts = 0;
  for (const auto& p : points) lifts += !p.pen;
  EXPECT_EQ(lifts, 2);  // each stroke began with a pen-up arrival
}

TEST(CanvasPenInput, TimeLimitCountsFromTheFirstPenDown) {
  CanvasPenInput pen(multi_stroke_rules());
  const Camera2D cam = camera();
  pen.tick(100.0);  // reading the word is free
  EXPECT_FALSE(pen.ended());
  EXPECT_DOUBLE_EQ(pen.seconds_left(100.0), 20.0);
  pen.feed({100.0, px(10, 150), true}, cam);
  EXPECT_DOUBLE_EQ(pen.seconds_left(105.0), 15.0);
  pen.tick(119.9);
  EXPECT_FALSE(pen.ended());
  pen.tick(120.1);
  EXPECT_EQ(pen.end_reason(), TrialEnd::TimeLimit);
}

TEST(CanvasPenInput, DoneBeforeWritingEndsAnEmptyTrialAndTimeNeverGoesBack) {
  CanvasPenInput empty(classic_rules());
  empty.done(3.0);
  EXPECT_TRUE(empty.ended());
  EXPECT_TRUE(empty.raw().points.empty());

  CanvasPenInput pen(classic_rules());
  const Camera2D cam = camera();
  pen.feed({5.000, px(10, 150), true}, cam);
  pen.feed({5.020, px(12, 150), true}, cam);
  pen.feed({5.019, px(14, 150), true}, cam);  // a millisecond event stamp just before the frame's poll time
  const auto times = pen.raw().times;
  ASSERT_EQ(times.size(), 3u);
  EXPECT_GE(times[2], times[1]);
}

TEST(CanvasPenInput, PauseStopsTheClockDropsSamplesAndLeavesThePausedSpanOutOfTheTrace) {
  CanvasPenInput pen(classic_rules());
  const Camera2D cam = camera();
  pen.feed({10.0, px(10, 150), true}, cam);
  pen.feed({11.0, px(20, 150), true}, cam);
  pen.pause(12.0);
  EXPECT_TRUE(pen.paused());
  pen.feed({20.0, px(200, 100), true}, cam);   // moved while paused: not ink
  pen.feed({25.0, px(200, 100), false}, cam);  // released while paused: does not end the classic trial
  pen.tick(100.0);                             // far past the 20 s limit in wall time
  EXPECT_FALSE(pen.ended());
  EXPECT_DOUBLE_EQ(pen.seconds_left(100.0), 18.0);  // frozen at the pause
  pen.resume(112.0);                                // paused for 100 s
  EXPECT_FALSE(pen.paused());
  EXPECT_DOUBLE_EQ(pen.seconds_left(113.0), 17.0);
  pen.feed({113.0, px(30, 150), true}, cam);  // the held stroke goes on
  pen.feed({114.0, px(30, 150), false}, cam);
  ASSERT_TRUE(pen.ended());
  EXPECT_EQ(pen.end_reason(), TrialEnd::Released);
  const writing::TimedTrace trace = pen.raw();
  ASSERT_EQ(trace.points.size(), 3u);
  EXPECT_NEAR(trace.points[2].x, 30.0, 1e-3);  // nothing from the paused span
  EXPECT_DOUBLE_EQ(trace.times[1], 1.0);
  EXPECT_DOUBLE_EQ(trace.times[2], 3.0);  // 113 s wall time minus the 100 s pause, from the first touch at 10 s
}

TEST(CanvasPenInput, TimeLimitRunsOnlyWhileNotPaused) {
  CanvasPenInput pen(multi_stroke_rules());
  const Camera2D cam = camera();
  pen.feed({0.0, px(10, 150), true}, cam);
  pen.pause(5.0);
  pen.pause(50.0);  // a second pause does not move the start of the first
  pen.resume(60.0);
  pen.resume(70.0);  // not paused: nothing
  pen.tick(74.9);    // 19.9 s of trial time
  EXPECT_FALSE(pen.ended());
  pen.tick(75.1);
  EXPECT_EQ(pen.end_reason(), TrialEnd::TimeLimit);
}

}  // namespace
}  // namespace sc::writing_view
