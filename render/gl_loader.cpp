#include "render/gl_loader.h"

#include <string>

#include "engine/error.h"
#include "render/gl.h"

namespace hdprior::render {

#define HDPRIOR_GL_DEFINE(type, name) type name = nullptr;
HDPRIOR_GL_FUNCTIONS(HDPRIOR_GL_DEFINE)
#undef HDPRIOR_GL_DEFINE

void loadGlFunctions(GlProcLoader load, const char* source) {
#define HDPRIOR_GL_LOAD(type, name)                                                           \
  name = reinterpret_cast<type>(load(#name));                                                 \
  if (!name) throw Error(source, "the OpenGL context does not provide " + std::string(#name));
  HDPRIOR_GL_FUNCTIONS(HDPRIOR_GL_LOAD)
#undef HDPRIOR_GL_LOAD
}

}  // namespace hdprior::render
