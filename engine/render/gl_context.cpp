#include "engine/render/gl_context.hpp"

#include <cstdlib>
#include <string_view>

#include "engine/core/error.hpp"
#include "engine/render/offscreen_contexts.hpp"

namespace sc {

std::string GlContext::describe() const {
  auto text = [this](GLenum name) {
    const auto* value = reinterpret_cast<const char*>(gl_.GetString(name));
    return std::string(value != nullptr ? value : "?");
  };
  return text(GL_VERSION) + " / " + text(GL_RENDERER);
}

void GlContext::load_functions(GlProcLoader loader, const std::string& context_name) {
  gl_ = load_gl_functions(loader, context_name);
  GLint major = 0, minor = 0;
  gl_.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl_.GetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 33)
    throw InputError(context_name, "OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                                       " context, but 3.3 core is required");
}

bool is_software_renderer(const GlFunctions& gl) {
  const auto* value = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
  const std::string_view renderer = value != nullptr ? value : "";
  for (std::string_view cpu : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
    if (renderer.find(cpu) != std::string_view::npos) return true;
  return false;
}

int preferred_samples(const GlFunctions& gl) { return is_software_renderer(gl) ? 1 : 4; }

OffscreenBackend offscreen_backend_from_env() {
  const char* value = std::getenv("SKILLCOACH_GL");
  if (value == nullptr || *value == '\0' || std::string_view(value) == "osmesa") return OffscreenBackend::osmesa;
  if (std::string_view(value) == "egl") return OffscreenBackend::egl;
  throw InputError("SKILLCOACH_GL", "unknown offscreen backend '" + std::string(value) + "' (use osmesa or egl)");
}

std::string_view to_string(OffscreenBackend backend) { return backend == OffscreenBackend::osmesa ? "osmesa" : "egl"; }

std::unique_ptr<GlContext> create_offscreen_context(OffscreenBackend backend, int width, int height) {
  return backend == OffscreenBackend::osmesa ? create_osmesa_context(width, height) : create_egl_context(width, height);
}

std::unique_ptr<GlContext> create_offscreen_context_from_env(int width, int height) {
  const char* chosen = std::getenv("SKILLCOACH_GL");
  if (chosen != nullptr && *chosen != '\0')
    return create_offscreen_context(offscreen_backend_from_env(), width, height);
  try {
    return create_osmesa_context(width, height);
  } catch (const InputError& osmesa_error) {
    try {
      return create_egl_context(width, height);
    } catch (const InputError& egl_error) {
      throw InputError("offscreen OpenGL",
                       std::string("no context available: ") + osmesa_error.what() + "; " + egl_error.what());
    }
  }
}

}  // namespace sc
