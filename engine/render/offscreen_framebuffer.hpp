#pragma once
// The render target of offscreen contexts: a 4x multisampled RGBA8 + depth/stencil framebuffer that scenes are
// drawn into, and a single-sample RGBA8 framebuffer it is resolved into for reading. Both OSMesa and EGL use
// it, so the two backends rasterise into identical buffers and give the same pixels.
#include "engine/render/gl_functions.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

class OffscreenFramebuffer {
 public:
  static constexpr int kSamples = 4;

  OffscreenFramebuffer(const GlFunctions& gl, int width, int height);
  ~OffscreenFramebuffer();
  OffscreenFramebuffer(const OffscreenFramebuffer&) = delete;
  OffscreenFramebuffer& operator=(const OffscreenFramebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint draw_framebuffer() const { return multisampled_fbo_; }
  void resolve();          // multisampled -> readable
  RgbaImage read() const;  // the resolved image, top row first

 private:
  const GlFunctions& gl_;
  int width_;
  int height_;
  GLuint multisampled_fbo_ = 0;
  GLuint resolved_fbo_ = 0;
  GLuint color_ms_ = 0;
  GLuint depth_stencil_ms_ = 0;
  GLuint color_resolved_ = 0;
};

}  // namespace sc
