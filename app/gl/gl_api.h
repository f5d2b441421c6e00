// The OpenGL 3.3 core functions raylab calls, loaded at run time through the
// active backend's GetProcAddress (EGL, OSMesa or GLFW). No loader library:
// Debian has no glad, glbinding 2.1 has no custom resolver and libepoxy
// asserts under OSMesa. Call as gl::CreateShader(...), after gl::load().
#pragma once

#include <GL/glcorearb.h>

#include <functional>
#include <string>

#define RAYLAB_GL_FUNCTIONS(X)                                                        \
    X(PFNGLGETSTRINGPROC, GetString)                                                  \
    X(PFNGLGETERRORPROC, GetError)                                                    \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                              \
    X(PFNGLVIEWPORTPROC, Viewport)                                                    \
    X(PFNGLSCISSORPROC, Scissor)                                                      \
    X(PFNGLCLEARCOLORPROC, ClearColor)                                                \
    X(PFNGLCLEARPROC, Clear)                                                          \
    X(PFNGLFINISHPROC, Finish)                                                        \
    X(PFNGLFLUSHPROC, Flush)                                                          \
    X(PFNGLENABLEPROC, Enable)                                                        \
    X(PFNGLDISABLEPROC, Disable)                                                      \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                              \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                                \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                              \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                \
    X(PFNGLCREATESHADERPROC, CreateShader)                                            \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                            \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                          \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                              \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                    \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                            \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                          \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                            \
    X(PFNGLDETACHSHADERPROC, DetachShader)                                            \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                              \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                            \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                  \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                          \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                \
    X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)                            \
    X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding)                              \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                                  \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                                  \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                                  \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                                  \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                                  \
    X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                                \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                    \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                                \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                          \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                        \
    X(PFNGLBUFFERDATAPROC, BufferData)                                                \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                          \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                      \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                      \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                              \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                        \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                              \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                          \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                          \
    X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                                \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                          \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                      \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                      \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                            \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                        \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                      \
    X(PFNGLGENQUERIESPROC, GenQueries)                                                \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                          \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                                \
    X(PFNGLENDQUERYPROC, EndQuery)                                                    \
    X(PFNGLGETQUERYOBJECTIVPROC, GetQueryObjectiv)                                    \
    X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)                              \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                    \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                              \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                    \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                              \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                      \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                          \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                  \
    X(PFNGLDEPTHMASKPROC, DepthMask)

namespace gl {

#define RAYLAB_GL_DECLARE(type, name) extern type name;
RAYLAB_GL_FUNCTIONS(RAYLAB_GL_DECLARE)
#undef RAYLAB_GL_DECLARE

using ProcResolver = std::function<void*(const char* name)>;

// Resolves every function above; throws rl::Error naming the first missing
// one. Called by each context after it is made current.
void load(const ProcResolver& resolve);

// "GL_INVALID_OPERATION" etc., for error messages.
std::string errorName(GLenum error);

}  // namespace gl
