#pragma once
// The trainer window: an SDL2 window (resizable, high-DPI aware) with an OpenGL 3.3 core context,
// 4x multisampling when available and an 8-bit stencil buffer. The caller has initialised SDL video.
#include <string>

#include "engine/render/gl_context.hpp"

struct SDL_Window;

namespace sc {

class SdlWindowContext final : public GlContext {
 public:
  // Throws InputError("SDL window", <SDL_GetError()>) when no window or context can be created.
  SdlWindowContext(const std::string& title, int width_points, int height_points);
  ~SdlWindowContext() override;

  std::string_view backend_name() const override { return "sdl"; }
  void make_current() override;
  int width() const override;  // drawable pixels
  int height() const override;
  GLuint target_framebuffer() const override { return 0; }
  void present() override;         // swaps buffers
  RgbaImage read_rgba() override;  // back buffer; call before present()
  void resize(int, int) override {}

  SDL_Window* window() const { return window_; }
  void* sdl_gl_context() const { return context_; }
  // Drawable pixels per window point (2 on a typical high-DPI display).
  float pixel_density() const;

 private:
  SDL_Window* window_ = nullptr;
  void* context_ = nullptr;  // SDL_GLContext
};

}  // namespace sc
