#pragma once
#include <filesystem>

#include "engine/eval/rgb_image.h"
#include "render/image.h"

namespace hdprior::render {

// Encodes as PNG and writes atomically (temporary name + rename); throws Error naming the
// file on failure, leaving nothing behind.
void writePng(const std::filesystem::path& path, const Image& image);
// The same for the engine's GPU-free figures (box plots, `hdprior plot`), opaque.
void writePng(const std::filesystem::path& path, const RgbImage& image);

}  // namespace hdprior::render
