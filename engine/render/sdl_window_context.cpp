#include "engine/render/sdl_window_context.hpp"

#include <SDL.h>

#include <cstring>

#include "engine/core/error.hpp"

namespace sc {
namespace {

GlProc sdl_proc(const char* name) { return reinterpret_cast<GlProc>(SDL_GL_GetProcAddress(name)); }

void request_attributes(int samples) {
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, samples > 0 ? 1 : 0);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, samples);
}

}  // namespace

SdlWindowContext::SdlWindowContext(const std::string& title, int width_points, int height_points) {
  const Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
  // Multisampling is not offered by every driver; a window without it is still better than none. On a software
  // renderer the window is opened again without it: there MSAA multiplies the rasteriser's work, and the
  // renderer's feathered edges are smooth without it.
  for (int samples : {4, 0}) {
    request_attributes(samples);
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width_points,
                               height_points, flags);
    if (window_ == nullptr) continue;
    context_ = SDL_GL_CreateContext(window_);
    if (context_ != nullptr) {
      SDL_GL_MakeCurrent(window_, context_);
      load_functions(&sdl_proc, "SDL window");
      if (samples == 0 || preferred_samples(gl()) > 1) break;
      SDL_GL_DeleteContext(context_);
      context_ = nullptr;
    }
    SDL_DestroyWindow(window_);
    window_ = nullptr;
  }
  if (window_ == nullptr || context_ == nullptr)
    throw InputError("SDL window", std::string("cannot open an OpenGL 3.3 core window: ") + SDL_GetError());
  SDL_GL_SetSwapInterval(1);  // vsync: render at display rate
  set_current_gl_functions(&gl());
}

SdlWindowContext::~SdlWindowContext() {
  if (current_gl_functions() == &gl()) set_current_gl_functions(nullptr);
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
}

void SdlWindowContext::make_current() {
  SDL_GL_MakeCurrent(window_, context_);
  set_current_gl_functions(&gl());
}

int SdlWindowContext::width() const {
  int w = 0, h = 0;
  SDL_GL_GetDrawableSize(window_, &w, &h);
  return w;
}

int SdlWindowContext::height() const {
  int w = 0, h = 0;
  SDL_GL_GetDrawableSize(window_, &w, &h);
  return h;
}

float SdlWindowContext::pixel_density() const {
  int points_w = 0, points_h = 0;
  SDL_GetWindowSize(window_, &points_w, &points_h);
  return points_w > 0 ? static_cast<float>(width()) / static_cast<float>(points_w) : 1.0f;
}

void SdlWindowContext::present() { SDL_GL_SwapWindow(window_); }

RgbaImage SdlWindowContext::read_rgba() {
  const int w = width(), h = height();
  RgbaImage bottom_up(w, h);
  gl().BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  gl().ReadBuffer(GL_BACK);
  gl().PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl().ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.pixels.data());
  RgbaImage image(w, h);
  for (int y = 0; y < h; ++y) std::memcpy(image.at(0, y), bottom_up.at(0, h - 1 - y), static_cast<std::size_t>(w) * 4);
  return image;
}

}  // namespace sc
