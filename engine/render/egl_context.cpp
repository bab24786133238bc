// EGL surfaceless offscreen context (EGL_PLATFORM_SURFACELESS_MESA) drawing into a framebuffer object.
// This is the offscreen path that keeps working on Mesa >= 25.1, which dropped OSMesa.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/offscreen_contexts.hpp"
#include "engine/render/offscreen_gl_context.hpp"

namespace sc {
namespace {

constexpr const char* kWhere = "EGL surfaceless";

std::string egl_error_text() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + code;
}

GlProc egl_proc(const char* name) { return reinterpret_cast<GlProc>(eglGetProcAddress(name)); }

class EglContext final : public OffscreenGlContext {
 public:
  EglContext(int width, int height) {
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display == nullptr) throw InputError(kWhere, "eglGetPlatformDisplayEXT is not available");
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || eglInitialize(display_, &major, &minor) == EGL_FALSE)
      throw InputError(kWhere, "no surfaceless EGL display (is libegl-mesa0 installed?): " + egl_error_text());
    const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
    if (extensions == nullptr || std::strstr(extensions, "EGL_KHR_surfaceless_context") == nullptr)
      throw InputError(kWhere, "the EGL display lacks EGL_KHR_surfaceless_context");
    if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE) throw InputError(kWhere, "desktop OpenGL is not supported");
    // The default EGL_SURFACE_TYPE is EGL_WINDOW_BIT, which a surfaceless display never offers.
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint config_count = 0;
    if (eglChooseConfig(display_, config_attribs, &config, 1, &config_count) == EGL_FALSE || config_count < 1)
      throw InputError(kWhere, "no EGL config for desktop OpenGL: " + egl_error_text());
    const EGLint context_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
    if (context_ == EGL_NO_CONTEXT)
      throw InputError(kWhere, "cannot create an OpenGL 3.3 core context: " + egl_error_text());
    bind_context();
    load_functions(&egl_proc, kWhere);
    attach_framebuffer(width, height);
  }

  ~EglContext() override {
    release_framebuffer();
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // No eglTerminate: the surfaceless display is a per-process singleton that other contexts may share.
  }

  std::string_view backend_name() const override { return "egl"; }

 private:
  void bind_context() override {
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_FALSE)
      throw InputError(kWhere, "eglMakeCurrent failed: " + egl_error_text());
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context(int width, int height) {
  return std::make_unique<EglContext>(width, height);
}

}  // namespace sc
