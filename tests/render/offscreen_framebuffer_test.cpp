#include "engine/render/offscreen_framebuffer.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/gl_context.hpp"

namespace sc {
namespace {

// Clears the framebuffer's draw target to a colour, resolves and reads it back.
RgbaImage cleared(const GlFunctions& gl, OffscreenFramebuffer& fb) {
  gl.BindFramebuffer(GL_FRAMEBUFFER, fb.draw_framebuffer());
  gl.Viewport(0, 0, fb.width(), fb.height());
  gl.Disable(GL_SCISSOR_TEST);
  gl.ClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  fb.resolve();
  return fb.read();
}

TEST(OffscreenFramebuffer, OneSampleAndMultisampledTargetsBothReadBackWhatWasDrawn) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), 64, 64);
  const GlFunctions& gl = context->gl();
  for (int samples : {1, 4}) {
    OffscreenFramebuffer fb(gl, 24, 16, samples);
    EXPECT_EQ(fb.samples(), samples);
    const RgbaImage image = cleared(gl, fb);
    ASSERT_EQ(image.width, 24);
    ASSERT_EQ(image.height, 16);
    const std::uint8_t* px = image.at(23, 15);
    EXPECT_NEAR(px[0], 51, 1) << samples << " samples";
    EXPECT_NEAR(px[1], 102, 1) << samples << " samples";
    EXPECT_NEAR(px[2], 153, 1) << samples << " samples";
  }
}

TEST(OffscreenFramebuffer, SoftwareRendererGetsOneSampleAndBadSampleCountsAreRefused) {
  // ctest pins GALLIUM_DRIVER=llvmpipe: a CPU rasteriser, where MSAA would multiply every pixel's cost.
  auto context = create_offscreen_context(offscreen_backend_from_env(), 64, 64);
  EXPECT_TRUE(is_software_renderer(context->gl())) << context->describe();
  EXPECT_EQ(preferred_samples(context->gl()), 1);
  EXPECT_THROW(OffscreenFramebuffer(context->gl(), 8, 8, 0), InputError);
  EXPECT_THROW(OffscreenFramebuffer(context->gl(), 8, 8, 17), InputError);
}

}  // namespace
}  // namespace sc
