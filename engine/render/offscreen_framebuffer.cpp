#include "engine/render/offscreen_framebuffer.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "engine/core/error.hpp"

namespace sc {

OffscreenFramebuffer::OffscreenFramebuffer(const GlFunctions& gl, int width, int height, int samples)
    : gl_(gl), width_(width), height_(height), samples_(samples) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw InputError("offscreen framebuffer",
                     "size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1..16384");
  if (samples < 1 || samples > 16)
    throw InputError("offscreen framebuffer", std::to_string(samples) + " samples is outside 1..16");
  gl_.GenRenderbuffers(1, &color_resolved_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, color_resolved_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  gl_.GenFramebuffers(1, &resolved_fbo_);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, resolved_fbo_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_resolved_);
  if (samples_ == 1) {  // scenes draw here: it needs the stencil of the ghost ribbons
    gl_.GenRenderbuffers(1, &depth_stencil_resolved_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, depth_stencil_resolved_);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil_resolved_);
  }
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw InputError("offscreen framebuffer", "resolve framebuffer is incomplete");
  if (samples_ > 1) create_multisampled();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer());
  throw_on_gl_error(gl_, "creating the offscreen framebuffer");
}

void OffscreenFramebuffer::create_multisampled() {
  gl_.GenRenderbuffers(1, &color_ms_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, color_ms_);
  gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width_, height_);
  gl_.GenRenderbuffers(1, &depth_stencil_ms_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, depth_stencil_ms_);
  gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH24_STENCIL8, width_, height_);
  gl_.GenFramebuffers(1, &multisampled_fbo_);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, multisampled_fbo_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_ms_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil_ms_);
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw InputError("offscreen framebuffer", "multisampled framebuffer is incomplete");
}

OffscreenFramebuffer::~OffscreenFramebuffer() {
  if (multisampled_fbo_ != 0) gl_.DeleteFramebuffers(1, &multisampled_fbo_);
  gl_.DeleteFramebuffers(1, &resolved_fbo_);
  if (color_ms_ != 0) gl_.DeleteRenderbuffers(1, &color_ms_);
  if (depth_stencil_ms_ != 0) gl_.DeleteRenderbuffers(1, &depth_stencil_ms_);
  gl_.DeleteRenderbuffers(1, &color_resolved_);
  if (depth_stencil_resolved_ != 0) gl_.DeleteRenderbuffers(1, &depth_stencil_resolved_);
}

void OffscreenFramebuffer::resolve() {
  if (samples_ == 1) return;
  gl_.Disable(GL_SCISSOR_TEST);  // a leftover scissor would clip the blit
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_fbo_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_fbo_);
  gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer());
}

RgbaImage OffscreenFramebuffer::read() const {
  RgbaImage bottom_up(width_, height_);
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_fbo_);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.pixels.data());
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, draw_framebuffer());
  throw_on_gl_error(gl_, "reading the offscreen framebuffer");
  RgbaImage image(width_, height_);
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) std::memcpy(image.at(0, y), bottom_up.at(0, height_ - 1 - y), row);
  return image;
}

}  // namespace sc
