// Renderer2D's static layers (engine/render/static_layer_cache.hpp): a layer copied from the cache gives the
// pixels drawing it gives, is redrawn when it changes, and is drawn as usual where a copy could differ.
#include "engine/render/static_layer_cache.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/renderer2d.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::test {
namespace {

struct Scene {
  float parked_x = -4;     // part of the layer
  float dot_x = 0;         // drawn over the layer every frame
  float ground_alpha = 1;  // < 1: the layer does not start with an opaque ground
};

class StaticLayer : public ::testing::Test {
 protected:
  RgbaImage frame(const Scene& s, bool layered) {
    renderer_.begin_frame(Color::hex(0x14181f));
    renderer_.set_camera(Camera2D({-10, -5, 10, 5}, {8, 4, 120, 60}, WorldYAxis::down));
    if (layered) renderer_.begin_static_layer();
    renderer_.fill_rect({{0, 0}, {10, 5}, 0}, Color::hex(0x646464).with_alpha(s.ground_alpha));
    renderer_.fill_rect({{s.parked_x, -2}, {2, 1}, 0.3f}, Color::hex(0xb04a3c));
    const std::array<Vec2f, 2> line{Vec2f{-9, 1}, Vec2f{9, 1.5f}};
    renderer_.polyline(line, Stroke::world(0.3f), Color::hex(0xffffff));
    for (int i = 0; i < 8; ++i)  // wheels: the bulk of the layer's triangles
      renderer_.fill_circle({-8.0f + 2.0f * static_cast<float>(i), 3.5f}, 0.6f, Color::hex(0x202020));
    if (layered) renderer_.end_static_layer();
    renderer_.fill_circle({s.dot_x, 2}, 1.2f, Color::hex(0x3d7be0, 0.8f));
    renderer_.end_frame();
    return context_->read_rgba();
  }
  void expect_same_as_drawn(const Scene& s, const RgbaImage& layered) {
    const RenderStats stats = renderer_.last_frame_stats();
    EXPECT_EQ(compare_images(layered, frame(s, false), 0).differing_pixels, 0u);
    stats_ = stats;
  }

  std::unique_ptr<GlContext> context_ = create_offscreen_context(offscreen_backend_from_env(), 136, 72);
  Renderer2D renderer_{*context_};
  RenderStats stats_;
};

TEST_F(StaticLayer, ACopyGivesThePixelsOfDrawingAndSkipsTheLayersTriangles) {
  const Scene first;
  expect_same_as_drawn(first, frame(first, true));  // drawn into the cache, then copied
  EXPECT_EQ(stats_.static_layer_copies, 1);
  const int drawn_vertices = stats_.vertices;
  Scene moved = first;
  moved.dot_x = 3;
  expect_same_as_drawn(moved, frame(moved, true));  // the same layer: copied only
  EXPECT_EQ(stats_.static_layer_copies, 1);
  EXPECT_LT(stats_.vertices, drawn_vertices / 2) << "the layer's triangles were drawn again";
}

TEST_F(StaticLayer, AChangedLayerIsDrawnAgainNotCopiedStale) {
  frame(Scene{}, true);
  Scene other;
  other.parked_x = 4;
  const RgbaImage layered = frame(other, true);
  const int vertices = renderer_.last_frame_stats().vertices;
  expect_same_as_drawn(other, layered);
  EXPECT_EQ(vertices, renderer_.last_frame_stats().vertices);  // layer and dot drawn, as without the cache
  EXPECT_GT(compare_images(layered, frame(Scene{}, false), 0).differing_pixels, 0u);
}

TEST_F(StaticLayer, ALayerWithoutAnOpaqueGroundIsDrawnAsUsual) {
  Scene translucent;
  translucent.ground_alpha = 0.5f;
  expect_same_as_drawn(translucent, frame(translucent, true));
  EXPECT_EQ(stats_.static_layer_copies, 0);
}

TEST_F(StaticLayer, LayersDoNotNestAndEndNeedsABegin) {
  renderer_.begin_frame(Color::hex(0));
  renderer_.begin_static_layer();
  EXPECT_THROW(renderer_.begin_static_layer(), InputError);
  renderer_.end_static_layer();
  EXPECT_THROW(renderer_.end_static_layer(), InputError);
  renderer_.end_frame();
  EXPECT_THROW(renderer_.begin_static_layer(), InputError);
}

}  // namespace
}  // namespace sc::test
