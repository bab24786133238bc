#include "engine/render/shader_program.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"

namespace sc {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot read shader");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

GLuint compile(const GlFunctions& gl, GLenum kind, std::string_view file_name) {
  const auto path = shader_path(file_name);  // throws naming the full path when missing
  const std::string source = read_text(path);
  const GLuint shader = gl.CreateShader(kind);
  const char* text = source.c_str();
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == 0) {
    char log[1024] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw InputError(path.string(), "shader does not compile: " + one_line(log));
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const GlFunctions& gl, std::string_view vertex_file, std::string_view fragment_file)
    : gl_(gl) {
  const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertex_file);
  GLuint fragment = 0;
  try {
    fragment = compile(gl, GL_FRAGMENT_SHADER, fragment_file);
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  program_ = gl.CreateProgram();
  gl.AttachShader(program_, vertex);
  gl.AttachShader(program_, fragment);
  gl.LinkProgram(program_);
  gl.DetachShader(program_, vertex);
  gl.DetachShader(program_, fragment);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = 0;
  gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok == 0) {
    char log[1024] = {};
    gl.GetProgramInfoLog(program_, sizeof log, nullptr, log);
    gl.DeleteProgram(program_);
    throw InputError(std::string(vertex_file) + " + " + std::string(fragment_file),
                     "shaders do not link: " + one_line(log));
  }
}

ShaderProgram::~ShaderProgram() { gl_.DeleteProgram(program_); }

GLint ShaderProgram::uniform(const char* name) const {
  const GLint location = gl_.GetUniformLocation(program_, name);
  if (location < 0) throw InputError("shader program", std::string("uniform ") + name + " not found");
  return location;
}

}  // namespace sc
