#include "render/offscreen_context.h"

#include <GL/osmesa.h>

#include <cstring>
#include <string>
#include <vector>

#include "engine/error.h"
#include "render/gl.h"

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
}

OffscreenContext::~OffscreenContext() {
  if (state_->context) OSMesaDestroyContext(state_->context);
}

void OffscreenContext::makeCurrent() {
  if (!OSMesaMakeCurrent(state_->context, state_->buffer.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw Error("OSMesa", "cannot make the offscreen context current");
}

Image OffscreenContext::readPixels() const {
  Image image{width_, height_, std::vector<uint8_t>(size_t(width_) * size_t(height_) * 4)};
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL rows run bottom to top; images (and PNG) top to bottom.
  const size_t stride = size_t(width_) * 4;
  std::vector<uint8_t> row(stride);
  for (int y = 0; y < height_ / 2; ++y) {
    uint8_t* a = image.rgba.data() + size_t(y) * stride;
    uint8_t* b = image.rgba.data() + size_t(height_ - 1 - y) * stride;
    std::memcpy(row.data(), a, stride);
    std::memcpy(a, b, stride);
    std::memcpy(b, row.data(), stride);
  }
  return image;
}

}  // namespace hdprior::render
