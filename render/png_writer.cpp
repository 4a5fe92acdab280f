#include "render/png_writer.h"

#include <cstdint>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include "engine/error.h"
#include "engine/io/file_bytes.h"

namespace hdprior::render {
namespace {

// `pixels`: width x height x channels bytes, rows top to bottom.
void writePixels(const std::filesystem::path& path, int width, int height, int channels, const std::vector<uint8_t>& pixels) {
  if (width <= 0 || height <= 0 || pixels.size() != size_t(width) * size_t(height) * size_t(channels))
    throw Error(path.string(), "cannot write an empty or malformed image");
  std::vector<uint8_t> bytes;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* begin = static_cast<const uint8_t*>(data);
    out->insert(out->end(), begin, begin + size);
  };
  if (!stbi_write_png_to_func(append, &bytes, width, height, channels, pixels.data(), width * channels))
    throw Error(path.string(), "PNG encoding failed");
  writeFileAtomically(path, bytes);
}

}  // namespace

void writePng(const std::filesystem::path& path, const Image& image) { writePixels(path, image.width, image.height, 4, image.rgba); }

void writePng(const std::filesystem::path& path, const RgbImage& image) { writePixels(path, image.width, image.height, 3, image.rgb); }

}  // namespace hdprior::render
