#pragma once
#include <filesystem>

#include "render/image.h"

namespace hdprior::render {

// Encodes as PNG and writes atomically (temporary name + rename); throws Error naming the
// file on failure, leaving nothing behind.
void writePng(const std::filesystem::path& path, const Image& image);

}  // namespace hdprior::render
