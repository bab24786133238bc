#include "engine/render/static_layer_cache.hpp"

#include "engine/core/error.hpp"

namespace sc {

StaticLayerCache::~StaticLayerCache() { release(); }

void StaticLayerCache::release() {
  if (color_ != 0) gl_.DeleteRenderbuffers(1, &color_);
  if (framebuffer_ != 0) gl_.DeleteFramebuffers(1, &framebuffer_);
  color_ = framebuffer_ = 0;
  width_ = height_ = 0;
  valid_ = false;
}

void StaticLayerCache::bind_for_drawing(std::uint64_t key, int width, int height) {
  if (framebuffer_ == 0 || width != width_ || height != height_) {
    release();
    gl_.GenFramebuffers(1, &framebuffer_);
    gl_.GenRenderbuffers(1, &color_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, color_);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      release();
      throw InputError("static layer cache", "the offscreen framebuffer is incomplete");
    }
    width_ = width;
    height_ = height;
  }
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  key_ = key;
  valid_ = true;
}

void StaticLayerCache::copy_to(GLuint target, int x, int y, int width, int height) const {
  // Unscissored, unscaled and of one format where it can be: Mesa then copies memory instead of drawing a quad.
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  gl_.BlitFramebuffer(x, y, x + width, y + height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, target);
}

}  // namespace sc
