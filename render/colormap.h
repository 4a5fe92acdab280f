#pragma once
#include <algorithm>

#include <Eigen/Core>

namespace hdprior::render {

// Google's Turbo colour map (polynomial fit), t clamped to [0, 1].
inline Eigen::Vector3f turbo(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f);
  const float r = 0.13572138f + x * (4.61539260f + x * (-42.66032258f + x * (132.13108234f + x * (-152.94239396f + x * 59.28637943f))));
  const float g = 0.09140261f + x * (2.19418839f + x * (4.84296658f + x * (-14.18503333f + x * (4.27729857f + x * 2.82956604f))));
  const float b = 0.10667330f + x * (12.64194608f + x * (-60.58204836f + x * (110.36276771f + x * (-89.90310912f + x * 27.34824973f))));
  return Eigen::Vector3f(r, g, b).cwiseMax(0.0f).cwiseMin(1.0f);
}

// A muted dark-blue -> teal -> sand ramp for terrain, so it does not compete with Turbo.
inline Eigen::Vector3f terrain(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f);
  const Eigen::Vector3f low(0.10f, 0.16f, 0.32f), mid(0.22f, 0.42f, 0.44f), high(0.78f, 0.72f, 0.52f);
  return x < 0.5f ? low + (mid - low) * (2 * x) : mid + (high - mid) * (2 * x - 1);
}

}  // namespace hdprior::render
