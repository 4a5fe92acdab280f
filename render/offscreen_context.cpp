#include "render/offscreen_context.h"

#include <GL/osmesa.h>

#include <string>
#include <vector>

#include "engine/error.h"
#include "render/framebuffer_readback.h"
#include "render/gl_loader.h"

namespace hdprior::render {

struct OffscreenContext::State {
  OSMesaContext context = nullptr;
  std::vector<uint8_t> buffer;
};

OffscreenContext::OffscreenContext(int width, int height)
    : state_(std::make_unique<State>()), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw Error("OSMesa", "bad framebuffer size " + std::to_string(width) + "x" + std::to_string(height));
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  state_->context = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!state_->context) throw Error("OSMesa", "cannot create an OpenGL 3.3 core-profile context");
  state_->buffer.resize(size_t(width) * size_t(height) * 4);
  makeCurrent();
  loadGlFunctions(OSMesaGetProcAddress, "OSMesa");
}

OffscreenContext::~OffscreenContext() {
  if (state_->context) OSMesaDestroyContext(state_->context);
}

void OffscreenContext::makeCurrent() {
  if (!OSMesaMakeCurrent(state_->context, state_->buffer.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw Error("OSMesa", "cannot make the offscreen context current");
}

Image OffscreenContext::readPixels() const { return readFramebuffer(width_, height_); }

}  // namespace hdprior::render
