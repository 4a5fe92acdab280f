#pragma once
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

}  // namespace hdprior
