#include "engine/odom/degraded_trajectory.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "engine/error.h"
#include "engine/io/text_lines.h"

namespace hdprior {
namespace {

// `out` = the whole of `text` as one finite number.
bool parseFinite(const std::string& text, double& out) {
  const std::optional<double> v = parseNumber(text);
  if (!v || !std::isfinite(*v)) return false;
  out = *v;
  return true;
}

// Box-Muller from the engine's raw output: std::normal_distribution's algorithm is the library's
// choice, this one is ours, so a seed gives the same trajectory everywhere.
double standardNormal(std::mt19937_64& rng) {
  const double u1 = (double(rng() >> 11) + 0.5) * 0x1.0p-53;
  const double u2 = double(rng() >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Eigen::Vector3d normalVector(std::mt19937_64& rng, double sigma) {
  const double x = standardNormal(rng), y = standardNormal(rng), z = standardNormal(rng);
  return sigma * Eigen::Vector3d(x, y, z);
}

SE3 randomStep(std::mt19937_64& rng, double length, const RandomWalk& walk) {
  const double scale = std::sqrt(length);
  const Eigen::Vector3d rotation = normalVector(rng, walk.rotationSigmaDeg * std::numbers::pi / 180.0 * scale);
  const Eigen::Vector3d translation = normalVector(rng, walk.translationSigma * scale);
  SE3 T = SE3::Identity();
  if (rotation.norm() > 0.0) T.linear() = Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).toRotationMatrix();
  T.translation() = translation;
  return T;
}

}  // namespace

RandomWalk parseRandomWalk(const std::string& text, const std::string& source) {
  const size_t comma = text.find(',');
  RandomWalk walk;
  if (comma == std::string::npos || !parseFinite(text.substr(0, comma), walk.translationSigma) ||
      !parseFinite(text.substr(comma + 1), walk.rotationSigmaDeg)) {
    throw Error(source, "'" + text + "' is not SIGMA_M,SIGMA_DEG (per sqrt(metre)), e.g. 0.002,0.002");
  }
  if (walk.translationSigma < 0 || walk.translationSigma > 1 || walk.rotationSigmaDeg < 0 || walk.rotationSigmaDeg > 1) {
    throw Error(source, "'" + text + "': each sigma must be in [0, 1]");
  }
  return walk;
}

std::vector<SE3> degradedPoses(const std::vector<SE3>& poses, const OdometryDrift& drift, const RandomWalk& walk) {
  if (poses.empty()) return poses;
  std::mt19937_64 rng(walk.seed);
  std::vector<SE3> out{poses.front()};
  for (size_t i = 1; i < poses.size(); ++i) {
    const SE3 step = poses[i - 1].inverse() * poses[i];
    SE3 degraded = driftedStep(step, drift);
    if (walk.active()) degraded = degraded * randomStep(rng, step.translation().norm(), walk);
    out.push_back(out.back() * degraded);
  }
  return out;
}

}  // namespace hdprior
