#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hdprior::render {

// An 8-bit RGBA image, rows top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4

  const uint8_t* pixel(int x, int y) const { return rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4; }
};

}  // namespace hdprior::render
