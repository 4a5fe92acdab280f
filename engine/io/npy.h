#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace hdprior {

enum class NpyDtype { Float16, Float32, Float64 };

// A C-order floating-point array from a .npy file. Values are widened/narrowed to float
// (float16 exactly; float64 rounded), which is what the engine's rasters hold.
struct NpyArray {
  NpyDtype dtype = NpyDtype::Float32;
  std::vector<size_t> shape;
  std::vector<float> values;
};

NpyArray parseNpy(std::span<const uint8_t> bytes, const std::string& source);
NpyArray readNpy(const std::filesystem::path& path);

std::vector<uint8_t> serializeNpy(const NpyArray& array);  // writes array.dtype
void writeNpy(const std::filesystem::path& path, const NpyArray& array);  // atomic

}  // namespace hdprior
