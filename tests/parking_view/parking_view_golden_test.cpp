// Golden images of the parking view (offscreen, GALLIUM_DRIVER=llvmpipe pinned by the test environment):
// the empty (classic) lot, the parked-car lot with a reverse-in goal, the car mid-manoeuvre in the reference's
// follow view, the expert's ghost path and ghost car over a learner's trail, and the driving gauges.
// The expert's trials are stored in tests/parking_view/data/ so a retuned planner does not move the goldens.
// Regenerate (planner trials included) with
//   SKILLCOACH_UPDATE_GOLDENS=1 ctest -R ParkingViewGolden   (then look at every PNG before committing).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking_view/driving_gauges.hpp"
#include "engine/parking_view/parking_scene.hpp"
#include "engine/parking_view/parking_trial_image.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "tests/support/golden_image.hpp"

namespace sc {
namespace {

constexpr int kWidth = 960;
constexpr int kHeight = 540;

bool updating_goldens() {
  const char* v = std::getenv("SKILLCOACH_UPDATE_GOLDENS");
  return v != nullptr && std::string_view(v) == "1";
}

// The expert's trial for `scenario`, planned and stored when goldens are updated, read otherwise.
ParkingTrial expert_trial(const ParkingScenario& scenario, std::string_view name) {
  const char* data = std::getenv("SKILLCOACH_TEST_DATA");
  const std::filesystem::path file =
      std::filesystem::path(data != nullptr ? data : "tests") / "parking_view" / "data" / (std::string(name) + ".json");
  if (updating_goldens()) write_parking_trial(file, ParkingExpert().plan(scenario).to_trial(scenario));
  return read_parking_trial(file);
}

ParkingScenario scenario_from_seed(std::uint64_t seed, LotVariant variant, double reverse_in) {
  Rng rng(seed);
  return sample_parking_scenario(rng, variant, reverse_in);
}

RgbaImage render_scene(const ParkingSceneView& view, CameraMode mode) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), kWidth, kHeight);
  Renderer2D renderer(*context);
  renderer.begin_frame(Color::hex(0x14181f));
  renderer.set_camera(parking_scene_camera(view, mode, {0, 0, kWidth, kHeight}));
  paint_parking_scene(renderer, view);
  renderer.end_frame();
  context->present();
  return context->read_rgba();
}

ParkingSceneView start_view(const ParkingScenario& scenario, const ParkingLayout& layout) {
  ParkingSceneView view;
  view.layout = &layout;
  view.goal = goal_pose(scenario);
  view.reverse_in = scenario.reverse_in;
  view.car = car_pose_of({0, 0, scenario.heading0, 0}, 0.0);
  return view;
}

TEST(ParkingViewGolden, EmptyLot) {
  ParkingScenario scenario;
  scenario.heading0 = 0.6;
  scenario.goal_spot = 4;
  const ParkingLayout layout = make_layout(scenario);
  EXPECT_TRUE(
      test::matches_golden(render_scene(start_view(scenario, layout), CameraMode::whole_lot), "parking/empty_lot"));
}

TEST(ParkingViewGolden, ParkedLotWithReverseInGoal) {
  ParkingScenario scenario;
  scenario.heading0 = 2.4;
  scenario.goal_spot = 20;
  scenario.variant = LotVariant::Parked;
  scenario.obstacle_seed = 77;
  scenario.reverse_in = true;
  const ParkingLayout layout = make_layout(scenario);
  EXPECT_TRUE(
      test::matches_golden(render_scene(start_view(scenario, layout), CameraMode::whole_lot), "parking/parked_lot"));
}

TEST(ParkingViewGolden, CarMidManoeuvreInTheReferenceView) {
  const ParkingScenario scenario = scenario_from_seed(8, LotVariant::Parked, 0.0);
  const ParkingTrial trial = expert_trial(scenario, "expert_mid_manoeuvre");
  const ParkingPath path = simulate_parking_path(trial);
  ASSERT_GT(path.samples.size(), 3u * 8);
  const std::vector<Vec2f> trail = path_points(path);
  const std::size_t at = 3 * 8;  // after control step 8
  const ParkingLayout layout = make_layout(scenario);
  ParkingSceneView view = start_view(scenario, layout);
  view.car = car_pose_of(path.samples[at].vehicle, path.samples[at].steering);
  view.trail = std::span<const Vec2f>(trail.data(), at + 1);
  EXPECT_TRUE(test::matches_golden(render_scene(view, CameraMode::follow_car), "parking/mid_manoeuvre"));
}

TEST(ParkingViewGolden, GhostPathAndGhostCarOverLearnerTrail) {
  // The expert first backs up (pink), then drives forward into the spot (blue).
  const ParkingScenario scenario = scenario_from_seed(3, LotVariant::Classic, 0.0);
  const ParkingPath expert = simulate_parking_path(expert_trial(scenario, "expert_ghost"));
  // A learner who went the wrong way: forward turning right, straightening, then braking into reverse.
  std::vector<ParkingAction> learner(5, ParkingAction{0.7, 0.5});
  learner.resize(10, ParkingAction{0.0, -0.4});
  learner.resize(15, ParkingAction{-0.8, 0.0});
  const ParkingPath learner_path = simulate_parking_path(scenario, learner);
  const std::vector<Vec2f> trail = path_points(learner_path);
  const ParkingLayout layout = make_layout(scenario);
  ParkingSceneView view = start_view(scenario, layout);
  view.car = car_pose_of(learner_path.samples.back().vehicle, learner_path.samples.back().steering);
  view.trail = trail;
  view.ghost_path = &expert;
  view.ghost_time = 0.45 * expert.duration();
  EXPECT_TRUE(test::matches_golden(render_scene(view, CameraMode::whole_lot), "parking/ghost_overlay"));
}

TEST(ParkingViewGolden, TrialImageWithExpertOverlayAndCaption) {
  const ParkingScenario scenario = scenario_from_seed(3, LotVariant::Classic, 0.0);
  const ParkingPath expert = simulate_parking_path(expert_trial(scenario, "expert_ghost"));
  ParkingTrial learner;
  learner.scenario = scenario;
  learner.actions.assign(20, ParkingAction{0.5, 0.6});
  auto context = create_offscreen_context(offscreen_backend_from_env(), 64, 64);
  ParkingTrialImageOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.expert = &expert;
  EXPECT_TRUE(test::matches_golden(render_parking_trial_image(*context, learner, options), "parking/trial_image"));
}

RgbaImage render_gauges(int width, int height, const DrivingGaugeValues& values) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), width, height);
  Renderer2D renderer(*context);
  ImGuiLayer imgui(*context);
  RgbaImage image;
  for (int frame = 0; frame < 2; ++frame) {  // ImGui's first frame differs (stack notes §3)
    imgui.make_current();
    imgui.begin_frame(1.0 / 60.0);
    renderer.begin_frame(Color::hex(0x646464));
    renderer.end_frame();
    const float s = imgui.scale();
    const GaugeLayout layout =
        layout_driving_gauges({static_cast<float>(width) - 16 * s, static_cast<float>(height) - 16 * s}, s);
    draw_driving_gauges(*ImGui::GetBackgroundDrawList(), layout, values, s);
    imgui.end_frame();
    context->present();
  }
  return context->read_rgba();
}

TEST(ParkingViewGolden, DrivingGaugesReversingWithTheExpertsStick) {
  DrivingGaugeValues values;
  values.speed = -3.4;
  values.steering = -0.5;
  values.stick = {-0.98, -0.69};  // a corner of the action square: reachable on the round stick
  values.stick_caption = "expert's stick";
  EXPECT_TRUE(test::matches_golden(render_gauges(640, 360, values), "parking/gauges"));
}

TEST(DrivingGauges, LayoutScalesWithTheUiScale) {
  const GaugeLayout at_720 = layout_driving_gauges({1264, 704}, 1.0f);
  const GaugeLayout at_4k = layout_driving_gauges({3792, 2112}, 3.0f);
  EXPECT_FLOAT_EQ(at_4k.radius, 3 * at_720.radius);
  EXPECT_FLOAT_EQ(at_4k.max.x - at_4k.min.x, 3 * (at_720.max.x - at_720.min.x));
  // Three dials side by side inside the panel, stick last (the mouse joystick sits there).
  EXPECT_LT(at_720.speed.x, at_720.steering.x);
  EXPECT_LT(at_720.steering.x, at_720.stick.x);
  EXPECT_LE(at_720.stick.x + at_720.radius, at_720.max.x);
  EXPECT_GE(at_720.speed.x - at_720.radius, at_720.min.x);
  // Small enough for 1280x720: under a third of the width.
  EXPECT_LT(at_720.max.x - at_720.min.x, 1280.0f / 3);
}

}  // namespace
}  // namespace sc
