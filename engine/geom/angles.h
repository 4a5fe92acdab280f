#pragma once
#include <numbers>

namespace hdprior {

// One degree in radians: options and outputs are in degrees, the maths in radians.
inline constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace hdprior
