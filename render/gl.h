#pragma once
// The one place that includes OpenGL. The renderer calls GL through one table of function
// pointers (the names below, in namespace hdprior::render), filled by loadGlFunctions when a
// context is created: OSMesaGetProcAddress for the offscreen buffer, glfwGetProcAddress for a
// window. So the same code draws into both, and libOSMesa and libGL (GLX), which export the
// same global symbols, can share a process. Include this only from .cpp files in
// namespace hdprior::render; <GL/glcorearb.h> without GL_GLEXT_PROTOTYPES gives types only.
#include <GL/glcorearb.h>

// Every GL function the renderer uses: add a line here to use another one.
#define HDPRIOR_GL_FUNCTIONS(X)                                   \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                      \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                        \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                            \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                  \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                  \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)    \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)            \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)          \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)  \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                  \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)          \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                          \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                  \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                              \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)              \
  X(PFNGLBUFFERDATAPROC, glBufferData)                            \
  X(PFNGLCLEARPROC, glClear)                                      \
  X(PFNGLCLEARCOLORPROC, glClearColor)                            \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                      \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                      \
  X(PFNGLCREATESHADERPROC, glCreateShader)                        \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                      \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                      \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                        \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                    \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)            \
  X(PFNGLDISABLEPROC, glDisable)                                  \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                            \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                        \
  X(PFNGLENABLEPROC, glEnable)                                    \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)  \
  X(PFNGLFINISHPROC, glFinish)                                    \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                            \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                          \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                  \
  X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                    \
  X(PFNGLGETERRORPROC, glGetError)                                \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                          \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)              \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                        \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                          \
  X(PFNGLGETSTRINGPROC, glGetString)                              \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)            \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                          \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                          \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                            \
  X(PFNGLREADPIXELSPROC, glReadPixels)                            \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                        \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                            \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                      \
  X(PFNGLTEXPARAMETERIVPROC, glTexParameteriv)                    \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                              \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                              \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                            \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                            \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)          \
  X(PFNGLVIEWPORTPROC, glViewport)

namespace hdprior::render {

#define HDPRIOR_GL_DECLARE(type, name) extern type name;
HDPRIOR_GL_FUNCTIONS(HDPRIOR_GL_DECLARE)
#undef HDPRIOR_GL_DECLARE

}  // namespace hdprior::render
