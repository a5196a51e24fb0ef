#pragma once
// OpenGL entry points through one table, filled at run time from OSMesa (headless) or GLFW (window).
// Linking libGL and libOSMesa into one binary makes GL_VERSION come back null, so the binary links
// neither: every `glFoo` below is a macro for `bsim::gl_table.Foo`. This header is also force-included
// into Dear ImGui's OpenGL3 backend (compiled with IMGUI_IMPL_OPENGL_LOADER_CUSTOM) so it shares the table.
#include <GL/glcorearb.h>

#include "gl_loader.h"

#define BSIM_GL_FUNCTIONS(X)                                                 \
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
  X(PFNGLBLENDFUNCPROC, BlendFunc)                                           \
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
  X(PFNGLCULLFACEPROC, CullFace)                                             \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                         \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                   \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                       \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                     \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                         \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                           \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                           \
  X(PFNGLDETACHSHADERPROC, DetachShader)                                     \
  X(PFNGLDISABLEPROC, Disable)                                               \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                         \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                                     \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)                 \
  X(PFNGLENABLEPROC, Enable)                                                 \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)               \
  X(PFNGLFINISHPROC, Finish)                                                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)               \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                         \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                                 \
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
  X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                                   \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                                         \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                         \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample) \
  X(PFNGLSCISSORPROC, Scissor)                                               \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                     \
  X(PFNGLSTENCILFUNCPROC, StencilFunc)                                       \
  X(PFNGLSTENCILMASKPROC, StencilMask)                                       \
  X(PFNGLSTENCILOPPROC, StencilOp)                                           \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                         \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                   \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                           \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                           \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                                           \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                         \
  X(PFNGLUNIFORM4FPROC, Uniform4f)                                           \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                             \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                             \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                         \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                       \
  X(PFNGLVIEWPORTPROC, Viewport)

namespace bsim {

struct GlTable {
#define BSIM_GL_MEMBER(type, name) type name = nullptr;
  BSIM_GL_FUNCTIONS(BSIM_GL_MEMBER)
#undef BSIM_GL_MEMBER
};

extern GlTable gl_table;

}  // namespace bsim

#define glActiveTexture ::bsim::gl_table.ActiveTexture
#define glAttachShader ::bsim::gl_table.AttachShader
#define glBindBuffer ::bsim::gl_table.BindBuffer
#define glBindFramebuffer ::bsim::gl_table.BindFramebuffer
#define glBindRenderbuffer ::bsim::gl_table.BindRenderbuffer
#define glBindSampler ::bsim::gl_table.BindSampler
#define glBindTexture ::bsim::gl_table.BindTexture
#define glBindVertexArray ::bsim::gl_table.BindVertexArray
#define glBlendEquation ::bsim::gl_table.BlendEquation
#define glBlendEquationSeparate ::bsim::gl_table.BlendEquationSeparate
#define glBlendFunc ::bsim::gl_table.BlendFunc
#define glBlendFuncSeparate ::bsim::gl_table.BlendFuncSeparate
#define glBlitFramebuffer ::bsim::gl_table.BlitFramebuffer
#define glBufferData ::bsim::gl_table.BufferData
#define glBufferSubData ::bsim::gl_table.BufferSubData
#define glCheckFramebufferStatus ::bsim::gl_table.CheckFramebufferStatus
#define glClear ::bsim::gl_table.Clear
#define glClearColor ::bsim::gl_table.ClearColor
#define glClearStencil ::bsim::gl_table.ClearStencil
#define glColorMask ::bsim::gl_table.ColorMask
#define glCompileShader ::bsim::gl_table.CompileShader
#define glCreateProgram ::bsim::gl_table.CreateProgram
#define glCreateShader ::bsim::gl_table.CreateShader
#define glCullFace ::bsim::gl_table.CullFace
#define glDeleteBuffers ::bsim::gl_table.DeleteBuffers
#define glDeleteFramebuffers ::bsim::gl_table.DeleteFramebuffers
#define glDeleteProgram ::bsim::gl_table.DeleteProgram
#define glDeleteRenderbuffers ::bsim::gl_table.DeleteRenderbuffers
#define glDeleteShader ::bsim::gl_table.DeleteShader
#define glDeleteTextures ::bsim::gl_table.DeleteTextures
#define glDeleteVertexArrays ::bsim::gl_table.DeleteVertexArrays
#define glDepthFunc ::bsim::gl_table.DepthFunc
#define glDepthMask ::bsim::gl_table.DepthMask
#define glDetachShader ::bsim::gl_table.DetachShader
#define glDisable ::bsim::gl_table.Disable
#define glDrawArrays ::bsim::gl_table.DrawArrays
#define glDrawElements ::bsim::gl_table.DrawElements
#define glDrawElementsBaseVertex ::bsim::gl_table.DrawElementsBaseVertex
#define glEnable ::bsim::gl_table.Enable
#define glEnableVertexAttribArray ::bsim::gl_table.EnableVertexAttribArray
#define glFinish ::bsim::gl_table.Finish
#define glFramebufferRenderbuffer ::bsim::gl_table.FramebufferRenderbuffer
#define glGenBuffers ::bsim::gl_table.GenBuffers
#define glGenerateMipmap ::bsim::gl_table.GenerateMipmap
#define glGenFramebuffers ::bsim::gl_table.GenFramebuffers
#define glGenRenderbuffers ::bsim::gl_table.GenRenderbuffers
#define glGenTextures ::bsim::gl_table.GenTextures
#define glGenVertexArrays ::bsim::gl_table.GenVertexArrays
#define glGetAttribLocation ::bsim::gl_table.GetAttribLocation
#define glGetError ::bsim::gl_table.GetError
#define glGetIntegerv ::bsim::gl_table.GetIntegerv
#define glGetProgramInfoLog ::bsim::gl_table.GetProgramInfoLog
#define glGetProgramiv ::bsim::gl_table.GetProgramiv
#define glGetShaderInfoLog ::bsim::gl_table.GetShaderInfoLog
#define glGetShaderiv ::bsim::gl_table.GetShaderiv
#define glGetString ::bsim::gl_table.GetString
#define glGetStringi ::bsim::gl_table.GetStringi
#define glGetUniformLocation ::bsim::gl_table.GetUniformLocation
#define glIsEnabled ::bsim::gl_table.IsEnabled
#define glLinkProgram ::bsim::gl_table.LinkProgram
#define glPixelStorei ::bsim::gl_table.PixelStorei
#define glPolygonMode ::bsim::gl_table.PolygonMode
#define glPolygonOffset ::bsim::gl_table.PolygonOffset
#define glReadBuffer ::bsim::gl_table.ReadBuffer
#define glReadPixels ::bsim::gl_table.ReadPixels
#define glRenderbufferStorageMultisample ::bsim::gl_table.RenderbufferStorageMultisample
#define glScissor ::bsim::gl_table.Scissor
#define glShaderSource ::bsim::gl_table.ShaderSource
#define glStencilFunc ::bsim::gl_table.StencilFunc
#define glStencilMask ::bsim::gl_table.StencilMask
#define glStencilOp ::bsim::gl_table.StencilOp
#define glTexImage2D ::bsim::gl_table.TexImage2D
#define glTexParameteri ::bsim::gl_table.TexParameteri
#define glUniform1f ::bsim::gl_table.Uniform1f
#define glUniform1i ::bsim::gl_table.Uniform1i
#define glUniform3f ::bsim::gl_table.Uniform3f
#define glUniform3fv ::bsim::gl_table.Uniform3fv
#define glUniform4f ::bsim::gl_table.Uniform4f
#define glUniformMatrix3fv ::bsim::gl_table.UniformMatrix3fv
#define glUniformMatrix4fv ::bsim::gl_table.UniformMatrix4fv
#define glUseProgram ::bsim::gl_table.UseProgram
#define glVertexAttribPointer ::bsim::gl_table.VertexAttribPointer
#define glViewport ::bsim::gl_table.Viewport
