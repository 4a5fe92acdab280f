#include "engine/odom/odometry_drift.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "engine/error.h"
#include "engine/io/text_lines.h"

namespace hdprior {
namespace {

constexpr const char* kDriftSyntax = "SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M], e.g. 0.007,0.5";

std::string numberText(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<std::string> commaSeparated(const std::string& text) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == ',') parts.emplace_back();
    else parts.back() += c;
  }
  return parts;
}

double radiansOver(double degPer100m, double metres) { return degPer100m / 100.0 * metres * std::numbers::pi / 180.0; }

}  // namespace

std::string odometryDriftProblem(const OdometryDrift& d) {
  if (!(std::abs(d.scale) < kMaxDriftScale)) return "scale = " + numberText(d.scale) + " is out of range (-0.2, 0.2)";
  if (!(std::abs(d.yawDegPer100m) <= kMaxDriftDegPer100m)) {
    return "yaw_deg_per_100m = " + numberText(d.yawDegPer100m) + " is out of range [-20, 20]";
  }
  if (!(std::abs(d.pitchDegPer100m) <= kMaxDriftDegPer100m)) {
    return "pitch_deg_per_100m = " + numberText(d.pitchDegPer100m) + " is out of range [-20, 20]";
  }
  return {};
}

OdometryDrift parseOdometryDrift(const std::string& text, const std::string& source) {
  const std::vector<std::string> parts = commaSeparated(text);
  if (parts.size() < 2 || parts.size() > 3) throw Error(source, "'" + text + "' is not " + kDriftSyntax);
  double values[3] = {0.0, 0.0, 0.0};
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::optional<double> v = parseNumber(parts[i]);
    if (!v || !std::isfinite(*v)) throw Error(source, "'" + parts[i] + "' is not a number (expected " + kDriftSyntax + ")");
    values[i] = *v;
  }
  const OdometryDrift drift{values[0], values[1], values[2]};
  if (const std::string problem = odometryDriftProblem(drift); !problem.empty()) throw Error(source, problem);
  return drift;
}

SE3 driftedStep(const SE3& step, const OdometryDrift& d) {
  const double length = step.translation().norm();
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(radiansOver(d.yawDegPer100m, length), Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(radiansOver(d.pitchDegPer100m, length), Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  SE3 out = SE3::Identity();
  out.linear() = turn * step.linear();
  out.translation() = (1.0 + d.scale) * step.translation();
  return out;
}

std::vector<SE3> driftedPoses(const std::vector<SE3>& poses, const OdometryDrift& drift) {
  if (!drift.active() || poses.empty()) return poses;
  std::vector<SE3> out{poses.front()};
  for (size_t i = 1; i < poses.size(); ++i) out.push_back(out.back() * driftedStep(poses[i - 1].inverse() * poses[i], drift));
  return out;
}

}  // namespace hdprior
