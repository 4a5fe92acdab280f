#pragma once
#include <cmath>
#include <cstdint>

namespace hdprior {

// SplitMix64's output function: a well-mixed 64-bit value from any seed, for deriving independent
// random streams (per sweep, per scene) from one seed.
inline uint64_t splitmix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A value in [0, 1) fixed for the cell of `cell` metres holding (x, y) and for `salt`: a texture
// every sweep sees the same.
inline double cellValue(double x, double y, double cell, uint64_t salt) {
  const auto col = uint64_t(int64_t(std::floor(x / cell))), row = uint64_t(int64_t(std::floor(y / cell)));
  return double(splitmix(splitmix(col ^ salt) ^ (row * 0x9e3779b97f4a7c15ULL)) >> 11) * 0x1.0p-53;
}

}  // namespace hdprior
