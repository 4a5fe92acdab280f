#pragma once
#include <filesystem>
#include <string>

#include "render/image.h"

namespace hdprior::test {

struct ImageDifference {
  bool sameSize = false;
  size_t differingPixels = 0;  // pixels with any channel off by more than the tolerance
  double differingFraction = 1.0;
  int maxChannelDifference = 255;
};

// Per-pixel comparison: a pixel differs when any of its RGBA channels differs by more
// than `tolerance`.
ImageDifference compareImages(const render::Image& actual, const render::Image& expected, int tolerance);
// Red where pixels differ, a dimmed grey copy of `expected` elsewhere.
render::Image differenceImage(const render::Image& actual, const render::Image& expected, int tolerance);

render::Image readPng(const std::filesystem::path& path);  // throws Error if unreadable

// Compares `actual` with tests/golden/<name>.png: at most `maxFraction` of the pixels may
// differ by more than `tolerance`. On failure writes <name>.actual.png and <name>.diff.png
// into the build's test output folder and says so in the returned message (empty on
// success). With HDPRIOR_UPDATE_GOLDEN=1 it (re)writes the golden instead and passes.
std::string checkGolden(const render::Image& actual, const std::string& name, int tolerance = 24,
                        double maxFraction = 0.005);

}  // namespace hdprior::test
