#include "render/gpu_texture.h"

#include <algorithm>

#include "render/gl.h"

namespace hdprior::render {
namespace {

std::vector<uint8_t> shrink(int& width, int& height, const std::vector<uint8_t>& texels, int channels,
                            int factor) {
  const int w = (width + factor - 1) / factor, h = (height + factor - 1) / factor;
  std::vector<uint8_t> out(size_t(w) * size_t(h) * channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      unsigned sum[4] = {0, 0, 0, 0}, n = 0;
      for (int dy = 0; dy < factor && y * factor + dy < height; ++dy)
        for (int dx = 0; dx < factor && x * factor + dx < width; ++dx, ++n)
          for (int c = 0; c < channels; ++c)
            sum[c] += texels[(size_t(y * factor + dy) * width + (x * factor + dx)) * channels + c];
      for (int c = 0; c < channels; ++c) out[(size_t(y) * w + x) * channels + c] = uint8_t(sum[c] / n);
    }
  width = w;
  height = h;
  return out;
}

}  // namespace

GpuTexture::GpuTexture() { glGenTextures(1, &id_); }
GpuTexture::~GpuTexture() { glDeleteTextures(1, &id_); }

void GpuTexture::upload(int width, int height, const std::vector<uint8_t>& texels, TextureFormat format,
                        bool smooth) {
  const bool mask = format == TextureFormat::Mask8;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int factor = (std::max(width, height) + maxSize - 1) / maxSize;
  std::vector<uint8_t> reduced;
  const std::vector<uint8_t>* data = &texels;
  if (factor > 1) data = &(reduced = shrink(width, height, texels, mask ? 1 : 4, factor));
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, mask ? GL_R8 : GL_RGBA8, width, height, 0, mask ? GL_RED : GL_RGBA,
               GL_UNSIGNED_BYTE, data->data());
  if (mask) {
    const GLint swizzle[4] = {GL_ONE, GL_ONE, GL_ONE, GL_RED};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  }
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, smooth ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, smooth ? GL_LINEAR : GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void GpuTexture::bind(int unit) const {
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, id_);
}

}  // namespace hdprior::render
