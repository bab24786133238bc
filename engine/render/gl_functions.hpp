#pragma once
// The OpenGL entry points SkillCoach uses, loaded at run time from the current context's
// getProcAddress (SDL_GL_GetProcAddress, OSMesaGetProcAddress, eglGetProcAddress).
// Why not link libGL: libOSMesa exports every gl* symbol itself, so whichever library comes first at link
// time would win for all contexts (stack notes §3). Loading a table per context lets one binary use an SDL
// window, OSMesa and EGL.
#include <GL/glcorearb.h>

#include <string>

namespace sc {

// X(type, member): one line per GL function; member is the name without the "gl" prefix.
#define SC_GL_FUNCTION_LIST(X)                                               \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                   \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                     \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                         \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                               \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                             \
  X(PFNGLBINDSAMPLERPROC, BindSampler)                                       \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                       \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                               \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                   \
  X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate)                   \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                           \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                               \
  X(PFNGLBUFFERDATAPROC, BufferData)                                         \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                   \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                 \
  X(PFNGLCLEARPROC, Clear)                                                   \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                         \
  X(PFNGLCLEARSTENCILPROC, ClearStencil)                                     \
  X(PFNGLCOLORMASKPROC, ColorMask)                                           \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                                   \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                   \
  X(PFNGLCREATESHADERPROC, CreateShader)                                     \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                         \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                   \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                       \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                     \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                         \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                           \
  X(PFNGLDETACHSHADERPROC, DetachShader)                                     \
  X(PFNGLDISABLEPROC, Disable)                                               \
  X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)             \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                         \
  X(PFNGLDRAWBUFFERPROC, DrawBuffer)                                         \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                                     \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)                 \
  X(PFNGLENABLEPROC, Enable)                                                 \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)               \
  X(PFNGLFINISHPROC, Finish)                                                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)               \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                         \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                               \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                             \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                       \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                               \
  X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                           \
  X(PFNGLGETERRORPROC, GetError)                                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                           \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                     \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                             \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                       \
  X(PFNGLGETSTRINGPROC, GetString)                                           \
  X(PFNGLGETSTRINGIPROC, GetStringi)                                         \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                         \
  X(PFNGLISENABLEDPROC, IsEnabled)                                           \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                       \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                       \
  X(PFNGLPOLYGONMODEPROC, PolygonMode)                                       \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                                         \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                         \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                       \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample) \
  X(PFNGLSCISSORPROC, Scissor)                                               \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                     \
  X(PFNGLSTENCILFUNCPROC, StencilFunc)                                       \
  X(PFNGLSTENCILMASKPROC, StencilMask)                                       \
  X(PFNGLSTENCILOPPROC, StencilOp)                                           \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                         \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                   \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                           \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                                           \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                             \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                         \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                       \
  X(PFNGLVIEWPORTPROC, Viewport)

// Resolves a GL function name in the context that is current; returns nullptr if unknown.
using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

struct GlFunctions {
#define SC_GL_MEMBER(type, name) type name = nullptr;
  SC_GL_FUNCTION_LIST(SC_GL_MEMBER)
#undef SC_GL_MEMBER
};

// Loads every entry point; throws InputError("<context_name>: OpenGL function glX missing") if one is absent.
// The context must be current.
GlFunctions load_gl_functions(GlProcLoader loader, const std::string& context_name);

// The table of the context made current on this thread (nullptr if none). It exists only for code we do not
// own that calls gl* by name (the ImGui OpenGL3 backend, see gl_imgui_backend_shim.hpp); our own code holds
// a reference to its context's table instead. Thread-local because a GL context is current per thread.
const GlFunctions* current_gl_functions();
void set_current_gl_functions(const GlFunctions* functions);

// "glGetError() = 0x0502 after <what>" style checks, used after setup steps (not per draw call).
void throw_on_gl_error(const GlFunctions& gl, const std::string& what);

}  // namespace sc
