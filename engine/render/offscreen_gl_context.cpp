#include "engine/render/offscreen_gl_context.hpp"

namespace sc {

void OffscreenGlContext::make_current() {
  bind_context();
  if (framebuffer_) set_current_gl_functions(&gl());
}

void OffscreenGlContext::present() {
  framebuffer_->resolve();
  gl().Finish();
}

void OffscreenGlContext::resize(int width, int height) {
  if (width == this->width() && height == this->height()) return;
  make_current();
  framebuffer_.reset();
  framebuffer_.emplace(gl(), width, height, preferred_samples(gl()));
}

void OffscreenGlContext::attach_framebuffer(int width, int height) {
  set_current_gl_functions(&gl());
  framebuffer_.emplace(gl(), width, height, preferred_samples(gl()));
}

void OffscreenGlContext::release_framebuffer() {
  make_current();
  framebuffer_.reset();
  if (current_gl_functions() == &gl()) set_current_gl_functions(nullptr);
}

}  // namespace sc
