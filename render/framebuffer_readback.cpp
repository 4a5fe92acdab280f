#include "render/framebuffer_readback.h"

#include <cstring>
#include <vector>

#include "render/gl.h"

namespace hdprior::render {

Image readFramebuffer(int width, int height) {
  Image image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4)};
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL rows run bottom to top; images (and PNG) top to bottom.
  const size_t stride = size_t(width) * 4;
  std::vector<uint8_t> row(stride);
  for (int y = 0; y < height / 2; ++y) {
    uint8_t* a = image.rgba.data() + size_t(y) * stride;
    uint8_t* b = image.rgba.data() + size_t(height - 1 - y) * stride;
    std::memcpy(row.data(), a, stride);
    std::memcpy(a, b, stride);
    std::memcpy(b, row.data(), stride);
  }
  return image;
}

}  // namespace hdprior::render
