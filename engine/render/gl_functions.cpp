#include "engine/render/gl_functions.hpp"

#include <cstdio>

#include "engine/core/error.hpp"

namespace sc {
namespace {
thread_local const GlFunctions* t_current_functions = nullptr;
}  // namespace

GlFunctions load_gl_functions(GlProcLoader loader, const std::string& context_name) {
  GlFunctions gl;
#define SC_GL_LOAD(type, name)                          \
  gl.name = reinterpret_cast<type>(loader("gl" #name)); \
  if (gl.name == nullptr) throw InputError(context_name, "OpenGL function gl" #name " is missing");
  SC_GL_FUNCTION_LIST(SC_GL_LOAD)
#undef SC_GL_LOAD
  return gl;
}

const GlFunctions* current_gl_functions() { return t_current_functions; }
void set_current_gl_functions(const GlFunctions* functions) { t_current_functions = functions; }

void throw_on_gl_error(const GlFunctions& gl, const std::string& what) {
  const GLenum error = gl.GetError();
  if (error == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(error));
  throw InputError("OpenGL", std::string("error ") + code + " after " + what);
}

}  // namespace sc
