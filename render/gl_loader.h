#pragma once
// GL-header-free entry to the renderer's GL function table (render/gl.h).
namespace hdprior::render {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Fills the table from `load` (OSMesaGetProcAddress, glfwGetProcAddress) with a context current.
// Throws Error(source, ...) naming the first function the context does not provide.
void loadGlFunctions(GlProcLoader load, const char* source);

}  // namespace hdprior::render
