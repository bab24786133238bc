#pragma once
// What the OSMesa and EGL contexts have in common: both bind a context with no window surface and draw into
// an OffscreenFramebuffer, so size, present, read-back and resize are the same for both. A backend only says
// how to bind its context (bind_context) and allocates the framebuffer once its GL functions are loaded.
#include <optional>

#include "engine/render/gl_context.hpp"
#include "engine/render/offscreen_framebuffer.hpp"

namespace sc {

class OffscreenGlContext : public GlContext {
 public:
  void make_current() final;
  int width() const final { return framebuffer_->width(); }
  int height() const final { return framebuffer_->height(); }
  GLuint target_framebuffer() const final { return framebuffer_->draw_framebuffer(); }
  void present() final;
  RgbaImage read_rgba() final { return framebuffer_->read(); }
  void resize(int width, int height) final;

 protected:
  // Binds the backend's context to this thread; throws InputError when it cannot.
  virtual void bind_context() = 0;
  // Call once the context is bound and load_functions() has run.
  void attach_framebuffer(int width, int height);
  // Call first in the backend's destructor, while the context still exists: deletes the GL objects and
  // forgets the function table if it is the current one.
  void release_framebuffer();

 private:
  std::optional<OffscreenFramebuffer> framebuffer_;
};

}  // namespace sc
