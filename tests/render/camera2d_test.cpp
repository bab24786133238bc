#include "engine/render/camera2d.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/imgui_layer.hpp"

namespace sc {
namespace {

TEST(Camera2D, YDownMapsTopLeftToViewportTopLeft) {
  const Camera2D camera({0, 0, 16, 9}, {0, 0, 1280, 720}, WorldYAxis::down);
  EXPECT_FLOAT_EQ(camera.pixels_per_unit(), 80.0f);
  const Vec2f p = camera.world_to_pixel({0, 0});
  EXPECT_FLOAT_EQ(p.x, 0);
  EXPECT_FLOAT_EQ(p.y, 0);
  const Vec2f q = camera.world_to_pixel({16, 9});
  EXPECT_FLOAT_EQ(q.x, 1280);
  EXPECT_FLOAT_EQ(q.y, 720);
}

TEST(Camera2D, YUpFlipsAndRoundTrips) {
  const Camera2D camera({-1, -1, 1, 1}, {100, 50, 200, 200}, WorldYAxis::up);
  const Vec2f top = camera.world_to_pixel({0, 1});
  EXPECT_FLOAT_EQ(top.x, 200);
  EXPECT_FLOAT_EQ(top.y, 50);
  const Vec2f back = camera.pixel_to_world(camera.world_to_pixel({0.3f, -0.7f}));
  EXPECT_NEAR(back.x, 0.3f, 1e-6f);
  EXPECT_NEAR(back.y, -0.7f, 1e-6f);
}

TEST(Camera2D, LetterboxesKeepingAspectRatio) {
  const Camera2D camera({0, 0, 10, 10}, {0, 0, 400, 200});  // square world in a wide viewport
  EXPECT_FLOAT_EQ(camera.pixels_per_unit(), 20.0f);
  EXPECT_FLOAT_EQ(camera.world_to_pixel({0, 0}).x, 100.0f);
  const WorldRect visible = camera.visible_world();
  EXPECT_FLOAT_EQ(visible.min_x, -5.0f);
  EXPECT_FLOAT_EQ(visible.max_y, 10.0f);
}

TEST(Camera2D, RejectsEmptyWorldOrViewport) {
  EXPECT_THROW(Camera2D({0, 0, 0, 1}, {0, 0, 10, 10}), InputError);
  EXPECT_THROW(Camera2D({0, 0, 1, 1}, {0, 0, 0, 10}), InputError);
}

TEST(ImGuiLayerScale, FollowsFramebufferHeight) {
  EXPECT_FLOAT_EQ(ImGuiLayer::scale_for_height(720), 1.0f);
  EXPECT_FLOAT_EQ(ImGuiLayer::scale_for_height(2160), 3.0f);
  EXPECT_FLOAT_EQ(ImGuiLayer::scale_for_height(100), 0.75f);
  EXPECT_FLOAT_EQ(ImGuiLayer::scale_for_height(1080), 1.5f);
}

}  // namespace
}  // namespace sc
