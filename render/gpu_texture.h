#pragma once
#include <cstdint>
#include <vector>

namespace hdprior::render {

// Rgba8: 4 bytes per texel. Mask8: 1 byte per texel, read by shaders as (1, 1, 1, value),
// a quarter of the memory and upload time for masks such as the drivable raster.
enum class TextureFormat { Rgba8, Mask8 };

// A 2-D texture of 8-bit texels. Images larger than the context's maximum texture size are reduced
// by an integer factor (box filter) before upload. Needs a current context.
class GpuTexture {
 public:
  GpuTexture();
  ~GpuTexture();
  GpuTexture(const GpuTexture&) = delete;
  GpuTexture& operator=(const GpuTexture&) = delete;

  // texels: width * height * (4 or 1) bytes, row 0 at texture coordinate v = 0.
  void upload(int width, int height, const std::vector<uint8_t>& texels, TextureFormat format, bool smooth);
  void bind(int unit) const;

 private:
  unsigned id_ = 0;
};

}  // namespace hdprior::render
