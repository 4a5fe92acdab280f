#pragma once
#include <algorithm>

namespace hdprior {

// 0 below 0, 1 above 1, and the cubic 3x^2 - 2x^3 between: a ramp with flat ends.
inline double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace hdprior
