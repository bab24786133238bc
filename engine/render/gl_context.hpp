#pragma once
// One small interface over the three ways SkillCoach gets an OpenGL 3.3 core context:
//   - SdlWindowContext  (engine/render/sdl_window_context.hpp): the trainer window;
//   - OSMesa offscreen   (default for tests and headless screenshots);
//   - EGL surfaceless + FBO (Mesa >= 25.1 no longer ships OSMesa).
// Every context owns the table of GL entry points loaded from its own getProcAddress, so nothing in
// SkillCoach calls GL through link-time symbols.
#include <memory>
#include <string>
#include <string_view>

#include "engine/render/gl_functions.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // "sdl", "osmesa" or "egl".
  virtual std::string_view backend_name() const = 0;
  // Makes the context current on this thread (and its function table, for the ImGui backend).
  virtual void make_current() = 0;
  // Size of the drawable in pixels (for a high-DPI window this is larger than the window size in points).
  virtual int width() const = 0;
  virtual int height() const = 0;
  // The framebuffer object scenes are drawn into (0 for a window's default framebuffer).
  virtual GLuint target_framebuffer() const = 0;
  // Finishes a frame: swaps the window, or resolves the multisampled offscreen buffer.
  virtual void present() = 0;
  // The last finished frame (after present() for offscreen; for a window, the back buffer before present()).
  virtual RgbaImage read_rgba() = 0;
  // Offscreen contexts reallocate their buffers; a window ignores this (its size follows the window).
  virtual void resize(int width, int height) = 0;

  const GlFunctions& gl() const { return gl_; }
  // e.g. "4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string describe() const;

 protected:
  // Loads the function table; call once the context is current.
  void load_functions(GlProcLoader loader, const std::string& context_name);

 private:
  GlFunctions gl_;
};

// Whether the current context rasterises on the CPU (Mesa's llvmpipe, softpipe or swrast: a school PC or a VM
// without GPU drivers). There 4x MSAA costs every sample of every pixel, clears and resolve included, so
// offscreen targets and windows use one sample and rely on the renderer's feathered edges.
bool is_software_renderer(const GlFunctions& gl);
// The MSAA samples SkillCoach asks of a context: 1 on a software renderer, else 4.
int preferred_samples(const GlFunctions& gl);

enum class OffscreenBackend { osmesa, egl };

// SKILLCOACH_GL=osmesa|egl (default osmesa); throws InputError naming the variable for any other value.
OffscreenBackend offscreen_backend_from_env();
std::string_view to_string(OffscreenBackend backend);

// Creates and makes current an offscreen GL 3.3 core context with a width x height RGBA8 target
// (preferred_samples() samples, 8-bit stencil). Throws InputError with one line saying what is missing
// (e.g. libOSMesa.so.8 not installed, no EGL device) when no context can be made.
std::unique_ptr<GlContext> create_offscreen_context(OffscreenBackend backend, int width, int height);

// For the app's headless paths: SKILLCOACH_GL if set (that backend only); otherwise OSMesa, then EGL.
// Throws one InputError naming both failures when neither works.
std::unique_ptr<GlContext> create_offscreen_context_from_env(int width, int height);

}  // namespace sc
