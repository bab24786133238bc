#pragma once
// The render target of offscreen contexts: a readable single-sample RGBA8 + depth/stencil framebuffer, drawn
// into directly when `samples` is 1; with more samples, scenes are drawn into a multisampled RGBA8 +
// depth/stencil framebuffer that resolve() copies into the readable one. Both OSMesa and EGL use it, so the two
// backends rasterise into identical buffers and give the same pixels.
#include "engine/render/gl_functions.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

class OffscreenFramebuffer {
 public:
  OffscreenFramebuffer(const GlFunctions& gl, int width, int height, int samples);
  ~OffscreenFramebuffer();
  OffscreenFramebuffer(const OffscreenFramebuffer&) = delete;
  OffscreenFramebuffer& operator=(const OffscreenFramebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  GLuint draw_framebuffer() const { return samples_ > 1 ? multisampled_fbo_ : resolved_fbo_; }
  void resolve();          // multisampled -> readable (nothing to do with one sample)
  RgbaImage read() const;  // the resolved image, top row first

 private:
  void create_multisampled();

  const GlFunctions& gl_;
  int width_;
  int height_;
  int samples_;
  GLuint multisampled_fbo_ = 0;
  GLuint resolved_fbo_ = 0;
  GLuint color_ms_ = 0;
  GLuint depth_stencil_ms_ = 0;
  GLuint color_resolved_ = 0;
  GLuint depth_stencil_resolved_ = 0;
};

}  // namespace sc
