// Golden images of the 2D renderer on the offscreen backends.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/renderer2d.hpp"
#include "tests/render/primitives_scene.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::test {
namespace {

TEST(RendererGolden, PrimitivesSceneMatchesGoldenOnSelectedBackend) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), kPrimitivesWidth, kPrimitivesHeight);
  EXPECT_TRUE(matches_golden(render_primitives_scene(*context), "render/primitives"));
}

// Both offscreen backends rasterise with llvmpipe into the same framebuffer layout, so they must produce the
// same image: the suite can run on Mesa with or without OSMesa.
TEST(RendererGolden, OsmesaAndEglMatchTheSameGolden) {
  RgbaImage osmesa_image, egl_image;
  {
    auto osmesa = create_offscreen_context(OffscreenBackend::osmesa, kPrimitivesWidth, kPrimitivesHeight);
    osmesa_image = render_primitives_scene(*osmesa);
  }
  {
    auto egl = create_offscreen_context(OffscreenBackend::egl, kPrimitivesWidth, kPrimitivesHeight);
    egl_image = render_primitives_scene(*egl);
  }
  EXPECT_TRUE(matches_golden(osmesa_image, "render/primitives", {}, GoldenMode::compare_only));
  EXPECT_TRUE(matches_golden(egl_image, "render/primitives", {}, GoldenMode::compare_only));
}

// Frames must not depend on what was drawn before: render the scene, wreck GL state, render again.
TEST(RendererGolden, FrameStateIsResetEachFrame) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), kPrimitivesWidth, kPrimitivesHeight);
  const RgbaImage first = render_primitives_scene(*context);
  const GlFunctions& gl = context->gl();
  gl.Enable(GL_SCISSOR_TEST);
  gl.Scissor(0, 0, 10, 10);
  gl.BlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  gl.ColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  gl.Enable(GL_STENCIL_TEST);
  gl.StencilFunc(GL_NEVER, 1, 0xFF);
  gl.Enable(GL_CULL_FACE);
  gl.Viewport(5, 5, 20, 20);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  const RgbaImage second = render_primitives_scene(*context);
  const ImageDifference diff = compare_images(second, first, 0);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);
}

TEST(RendererGolden, SceneIsBatchedIntoFewDrawCalls) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), 320, 200);
  Renderer2D renderer(*context);
  renderer.begin_frame(Color::hex(0));
  for (int i = 0; i < 200; ++i) renderer.fill_circle({static_cast<float>(i), 50}, 3, Color::hex(0xffffff));
  const std::array<Vec2f, 3> path{Vec2f{0, 0}, Vec2f{100, 100}, Vec2f{200, 0}};
  renderer.ghost_ribbon(path, Stroke::pixels(8), Color::hex(0xffffff, 0.5f));
  for (int i = 0; i < 200; ++i) renderer.fill_rect({{static_cast<float>(i), 150}, {2, 2}, 0}, Color::hex(0xff0000));
  renderer.end_frame();
  // 200 circles in one call, the ghost in its own, 200 rectangles in one more.
  EXPECT_EQ(renderer.last_frame_stats().draw_calls, 3);
  EXPECT_GT(renderer.last_frame_stats().vertices, 200 * 36);
}

TEST(RendererGolden, OpaqueGroundOverAPixelAlignedViewportIsAClearOfTheSamePixels) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), 64, 48);
  Renderer2D renderer(*context);
  const Color ground = Color::hex(0x5a5f66);
  auto draw = [&](PixelViewport viewport, RotatedRect rect, Color color) {
    renderer.begin_frame(Color::hex(0x14181f));
    renderer.set_camera(Camera2D({-10, -5, 10, 5}, viewport, WorldYAxis::down));
    renderer.fill_rect(rect, color);
    renderer.end_frame();
    return context->read_rgba();
  };
  const RotatedRect whole{{0, 0}, {10, 5}, 0};
  const RgbaImage cleared = draw({8, 4, 40, 20}, whole, ground);
  EXPECT_EQ(renderer.last_frame_stats().vertices, 0);  // no triangles: a scissored clear
  // The same rectangle drawn as geometry (a hair larger than the viewport, so not a clear) gives the same image.
  const RgbaImage drawn = draw({8, 4, 40, 20}, {{0, 0}, {10.001f, 5.001f}, 0.0001f}, ground);
  EXPECT_GT(renderer.last_frame_stats().vertices, 0);
  EXPECT_EQ(compare_images(drawn, cleared, 0).differing_pixels, 0u);
  // Translucent, or over a viewport with fractional edges (whose edge pixels are partly covered): geometry.
  draw({8, 4, 40, 20}, whole, ground.with_alpha(0.5f));
  EXPECT_GT(renderer.last_frame_stats().vertices, 0);
  draw({8.5f, 4, 40, 20}, whole, ground);
  EXPECT_GT(renderer.last_frame_stats().vertices, 0);
}

// Ghost ribbons take stencil values 1..255; the 256th reuses 1 after the stencil is cleared again, so it
// must blend over the first where they overlap, exactly as a second ghost does.
TEST(RendererGolden, GhostAfterTheStencilValuesWrapStillBlends) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), 64, 64);
  Renderer2D renderer(*context);
  const std::array<Vec2f, 2> over{Vec2f{8, 16}, Vec2f{40, 16}};
  const std::array<Vec2f, 2> aside{Vec2f{8, 48}, Vec2f{40, 48}};
  const Color ghost = Color::hex(0xffffff, 0.3f);
  auto pixel_after = [&](int ghosts_between) {
    renderer.begin_frame(Color::hex(0x000000));
    renderer.ghost_ribbon(over, Stroke::pixels(8), ghost);
    for (int i = 0; i < ghosts_between; ++i) renderer.ghost_ribbon(aside, Stroke::pixels(8), ghost);
    renderer.ghost_ribbon(over, Stroke::pixels(8), ghost);
    renderer.end_frame();
    const RgbaImage image = context->read_rgba();
    return static_cast<int>(image.at(24, 16)[0]);  // red
  };
  const auto twice = pixel_after(0);
  EXPECT_GT(twice, 100);  // two blends of 30 % white: ~130, one would be ~77
  EXPECT_EQ(pixel_after(254), twice);
}

TEST(RendererGolden, UnknownBackendVariableIsAnInputError) {
  setenv("SKILLCOACH_GL", "vulkan", 1);
  EXPECT_THROW(offscreen_backend_from_env(), InputError);
  setenv("SKILLCOACH_GL", "egl", 1);
  EXPECT_EQ(offscreen_backend_from_env(), OffscreenBackend::egl);
  unsetenv("SKILLCOACH_GL");
  EXPECT_EQ(offscreen_backend_from_env(), OffscreenBackend::osmesa);
}

TEST(RendererGolden, MissingShaderNamesTheFile) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), 64, 64);
  setenv("SKILLCOACH_SHADER_DIR", "/nonexistent/shaders", 1);
  try {
    Renderer2D renderer(*context);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/shaders/scene.vert"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc::test
