#include "engine/odom/deskew.h"

#include <Eigen/Geometry>

namespace hdprior {

SE3 scaleMotion(const SE3& motion, double s) {
  const Eigen::AngleAxisd aa(motion.rotation());
  SE3 out = SE3::Identity();
  out.linear() = Eigen::AngleAxisd(aa.angle() * s, aa.axis()).toRotationMatrix();
  out.translation() = motion.translation() * s;
  return out;
}

Eigen::Vector3f deskewPoint(const LidarPoint& p, const SE3& motion, double periodNs) {
  const SE3 T = scaleMotion(motion, double(p.offsetNs) / periodNs);
  return (T * Eigen::Vector3d(p.x, p.y, p.z)).cast<float>();
}

std::vector<Eigen::Vector3f> deskewSweep(const std::vector<LidarPoint>& points, const SE3& motion, double periodNs) {
  // The motion is small and smooth: sample it at a few hundred offsets instead of per point.
  constexpr int kSteps = 256;
  int32_t maxOffset = 1;
  for (const auto& p : points) maxOffset = std::max(maxOffset, p.offsetNs);
  std::vector<Eigen::Matrix3f> R(kSteps + 1);
  std::vector<Eigen::Vector3f> t(kSteps + 1);
  for (int i = 0; i <= kSteps; ++i) {
    const SE3 T = scaleMotion(motion, double(maxOffset) * i / kSteps / periodNs);
    R[i] = T.rotation().cast<float>();
    t[i] = T.translation().cast<float>();
  }
  std::vector<Eigen::Vector3f> out(points.size());
  for (size_t j = 0; j < points.size(); ++j) {
    const auto& p = points[j];
    const int i = std::clamp(int(std::lround(double(p.offsetNs) / maxOffset * kSteps)), 0, kSteps);
    out[j] = R[i] * Eigen::Vector3f(p.x, p.y, p.z) + t[i];
  }
  return out;
}

std::vector<Eigen::Vector3f> sweepPositions(const std::vector<LidarPoint>& points) {
  std::vector<Eigen::Vector3f> out(points.size());
  for (size_t j = 0; j < points.size(); ++j) out[j] = {points[j].x, points[j].y, points[j].z};
  return out;
}

}  // namespace hdprior
