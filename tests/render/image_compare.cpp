#include "render/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

#include "engine/error.h"
#include "render/png_writer.h"

namespace hdprior::test {
namespace fs = std::filesystem;

namespace {

int pixelDifference(const render::Image& a, const render::Image& b, int x, int y) {
  const uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
  int d = 0;
  for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(p[c]) - int(q[c])));
  return d;
}

}  // namespace

ImageDifference compareImages(const render::Image& actual, const render::Image& expected, int tolerance) {
  ImageDifference r;
  r.sameSize = actual.width == expected.width && actual.height == expected.height;
  if (!r.sameSize || actual.width == 0) return r;
  r.maxChannelDifference = 0;
  for (int y = 0; y < actual.height; ++y)
    for (int x = 0; x < actual.width; ++x) {
      const int d = pixelDifference(actual, expected, x, y);
      r.maxChannelDifference = std::max(r.maxChannelDifference, d);
      if (d > tolerance) ++r.differingPixels;
    }
  r.differingFraction = double(r.differingPixels) / (double(actual.width) * actual.height);
  return r;
}

render::Image differenceImage(const render::Image& actual, const render::Image& expected, int tolerance) {
  render::Image diff{expected.width, expected.height, expected.rgba};
  for (int y = 0; y < diff.height; ++y)
    for (int x = 0; x < diff.width; ++x) {
      uint8_t* p = diff.rgba.data() + (size_t(y) * diff.width + x) * 4;
      const bool differs = pixelDifference(actual, expected, x, y) > tolerance;
      const uint8_t grey = uint8_t((p[0] + p[1] + p[2]) / 9);
      p[0] = differs ? 255 : grey;
      p[1] = differs ? 0 : grey;
      p[2] = differs ? 0 : grey;
      p[3] = 255;
    }
  return diff;
}

render::Image readPng(const fs::path& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) throw Error(path.string(), "cannot read PNG");
  render::Image image{w, h, std::vector<uint8_t>(data, data + size_t(w) * h * 4)};
  stbi_image_free(data);
  return image;
}

std::string checkGolden(const render::Image& actual, const std::string& name, int tolerance, double maxFraction) {
  const fs::path golden = fs::path(HDPRIOR_GOLDEN_DIR) / (name + ".png");
  const char* update = std::getenv("HDPRIOR_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    render::writePng(golden, actual);
    return "";
  }
  if (!fs::exists(golden)) return "no golden image " + golden.string() + " (run with HDPRIOR_UPDATE_GOLDEN=1)";
  const render::Image expected = readPng(golden);
  const ImageDifference d = compareImages(actual, expected, tolerance);
  if (d.sameSize && d.differingFraction <= maxFraction) return "";

  const fs::path dir = fs::path(HDPRIOR_TEST_OUTPUT) / "golden";
  fs::create_directories(dir);
  render::writePng(dir / (name + ".actual.png"), actual);
  std::ostringstream message;
  message << name << ": ";
  if (!d.sameSize) {
    message << "size " << actual.width << "x" << actual.height << " differs from the golden's " << expected.width
            << "x" << expected.height;
  } else {
    render::writePng(dir / (name + ".diff.png"), differenceImage(actual, expected, tolerance));
    message << d.differingFraction * 100 << "% of pixels differ by more than " << tolerance << " (allowed "
            << maxFraction * 100 << "%)";
  }
  message << "; actual and diff images in " << dir.string();
  return message.str();
}

}  // namespace hdprior::test
