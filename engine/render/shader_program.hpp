#pragma once
// A GLSL program built from two files in the shader folder (sc::shader_path). Compile and link errors become
// one InputError line naming the file and the compiler's first message.
#include <string_view>

#include "engine/render/gl_functions.hpp"

namespace sc {

class ShaderProgram {
 public:
  ShaderProgram(const GlFunctions& gl, std::string_view vertex_file, std::string_view fragment_file);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return program_; }
  // Throws InputError when the uniform does not exist (a renamed uniform must not fail silently).
  GLint uniform(const char* name) const;

 private:
  const GlFunctions& gl_;
  GLuint program_ = 0;
};

}  // namespace sc
