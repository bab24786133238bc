// OSMesa offscreen context. libOSMesa is opened with dlopen at run time instead of being linked: it exports
// every gl* symbol, which would shadow libGL for the SDL window and EGL (link-order trap, stack notes §3), and
// Mesa >= 25.1 no longer ships it, so a machine without it must still run everything else.
#include <dlfcn.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/offscreen_contexts.hpp"
#include "engine/render/offscreen_gl_context.hpp"

namespace sc {
namespace {

constexpr const char* kLibrary = "libOSMesa.so.8";
// Values from <GL/osmesa.h>, which we do not include because it pulls in <GL/gl.h> prototypes.
constexpr int kOsmesaFormat = 0x22;
constexpr int kOsmesaDepthBits = 0x30;
constexpr int kOsmesaStencilBits = 0x31;
constexpr int kOsmesaProfile = 0x33;
constexpr int kOsmesaCoreProfile = 0x34;
constexpr int kOsmesaMajorVersion = 0x36;
constexpr int kOsmesaMinorVersion = 0x37;

using OsmesaContextHandle = struct osmesa_context*;
using CreateContextAttribsFn = OsmesaContextHandle (*)(const int*, OsmesaContextHandle);
using DestroyContextFn = void (*)(OsmesaContextHandle);
using MakeCurrentFn = unsigned char (*)(OsmesaContextHandle, void*, GLenum, GLsizei, GLsizei);

struct OsmesaLibrary {
  CreateContextAttribsFn create_context_attribs = nullptr;
  DestroyContextFn destroy_context = nullptr;
  MakeCurrentFn make_current = nullptr;
  GlProcLoader get_proc_address = nullptr;
};

template <typename Fn>
Fn symbol(void* library, const char* name) {
  void* address = dlsym(library, name);
  if (address == nullptr) throw InputError(kLibrary, std::string("symbol ") + name + " is missing");
  return reinterpret_cast<Fn>(address);
}

OsmesaLibrary open_osmesa() {
  // Never dlclose()d: Mesa registers exit-time handlers, and unloading it under a live context crashes.
  void* library = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr)
    throw InputError(kLibrary,
                     "cannot load the OSMesa offscreen renderer (install libosmesa6, or use "
                     "SKILLCOACH_GL=egl): " +
                         one_line(dlerror()));
  OsmesaLibrary lib;
  lib.create_context_attribs = symbol<CreateContextAttribsFn>(library, "OSMesaCreateContextAttribs");
  lib.destroy_context = symbol<DestroyContextFn>(library, "OSMesaDestroyContext");
  lib.make_current = symbol<MakeCurrentFn>(library, "OSMesaMakeCurrent");
  lib.get_proc_address = symbol<GlProcLoader>(library, "OSMesaGetProcAddress");
  return lib;
}

class OsmesaContext final : public OffscreenGlContext {
 public:
  OsmesaContext(int width, int height) : lib_(open_osmesa()) {
    const int attribs[] = {kOsmesaFormat,
                           GL_RGBA,
                           kOsmesaDepthBits,
                           24,
                           kOsmesaStencilBits,
                           8,
                           kOsmesaProfile,
                           kOsmesaCoreProfile,
                           kOsmesaMajorVersion,
                           3,
                           kOsmesaMinorVersion,
                           3,
                           0};
    context_ = lib_.create_context_attribs(attribs, nullptr);
    if (context_ == nullptr) throw InputError(kLibrary, "OSMesaCreateContextAttribs failed for OpenGL 3.3 core");
    allocate(width, height);
  }

  ~OsmesaContext() override {
    release_framebuffer();
    lib_.destroy_context(context_);
  }

  std::string_view backend_name() const override { return "osmesa"; }

 private:
  void bind_context() override {
    // OSMesa needs a client buffer to bind; we draw into our own framebuffer object, so it stays 1x1.
    if (lib_.make_current(context_, default_buffer_.data(), GL_UNSIGNED_BYTE, 1, 1) == 0)
      throw InputError(kLibrary, "OSMesaMakeCurrent failed");
  }

  void allocate(int width, int height) {
    bind_context();
    load_functions(lib_.get_proc_address, kLibrary);
    attach_framebuffer(width, height);
  }

  OsmesaLibrary lib_;
  OsmesaContextHandle context_ = nullptr;
  std::vector<std::uint8_t> default_buffer_ = std::vector<std::uint8_t>(4, 0);
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context(int width, int height) {
  return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace sc
