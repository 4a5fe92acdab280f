#include "engine/lidar/ground_segmentation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Eigenvalues>

#include "engine/error.h"

namespace hdprior {
namespace {

void validate(const GroundSegmentationOptions& o) {
  GroundSegmentationOptions keys = o;
  checkOptionRanges("ground segmentation options", optionFields(keys));
  const auto bad = [](const std::string& why) { throw Error("ground segmentation options", why); };
  if (o.zoneRadii.empty() || o.zoneRadii.size() != o.zoneRings.size() || o.zoneRadii.size() != o.zoneSectors.size()) {
    bad("zoneRadii, zoneRings and zoneSectors must be non-empty and of equal length");
  }
  double previous = o.minRange;
  for (size_t z = 0; z < o.zoneRadii.size(); ++z) {
    if (!(o.zoneRadii[z] > previous)) bad("zone radii must increase beyond minRange");
    if (o.zoneRings[z] < 1 || o.zoneSectors[z] < 1 || o.zoneSectors[z] > 4096) bad("bad ring or sector count");
    previous = o.zoneRadii[z];
  }
  if (o.minBinPoints < 3 || o.seedPoints < 3 || o.iterations < 1) bad("minBinPoints, seedPoints or iterations out of range");
}

// Least-squares plane through points: unit normal (z >= 0) and centroid.
struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double distance(const Eigen::Vector3d& p) const { return std::abs(normal.dot(p - centroid)); }
};

Plane fitPlane(std::span<const Eigen::Vector3d> points, const std::vector<uint32_t>& members) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (uint32_t i : members) mean += points[i];
  mean /= double(members.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (uint32_t i : members) {
    const Eigen::Vector3d d = points[i] - mean;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(cov);
  Plane plane;
  plane.normal = eig.eigenvectors().col(0);
  // A single far ring crossing a bin is nearly a line, which leaves the plane free to turn
  // about it: take the plane through the line that is closest to horizontal instead.
  if (eig.eigenvalues()(1) < 0.02 * eig.eigenvalues()(2)) {
    const Eigen::Vector3d line = eig.eigenvectors().col(2);
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ() - line.z() * line;
    if (up.norm() > 1e-6) plane.normal = up.normalized();
  }
  if (plane.normal.z() < 0) plane.normal = -plane.normal;
  plane.centroid = mean;
  return plane;
}

// The zone, ring and sector layout flattened to bin indices.
class BinLayout {
 public:
  explicit BinLayout(const GroundSegmentationOptions& o) : o_(o) {
    int first = 0;
    for (size_t z = 0; z < o.zoneRadii.size(); ++z) {
      firstBin_.push_back(first);
      first += o.zoneRings[z] * o.zoneSectors[z];
    }
    binCount_ = first;
  }
  int binCount() const { return binCount_; }
  // -1 outside [minRange, maxRange).
  int binOf(const Eigen::Vector3d& p) const {
    const double r = std::hypot(p.x(), p.y());
    if (!(r >= o_.minRange && r < std::min(o_.maxRange, o_.zoneRadii.back()))) return -1;
    double inner = o_.minRange;
    for (size_t z = 0; z < o_.zoneRadii.size(); ++z) {
      if (r < o_.zoneRadii[z]) {
        const int ring = std::min(o_.zoneRings[z] - 1, int((r - inner) / (o_.zoneRadii[z] - inner) * o_.zoneRings[z]));
        double a = std::atan2(p.y(), p.x()) + std::numbers::pi;
        const int sector = std::min(o_.zoneSectors[z] - 1, int(a / (2 * std::numbers::pi) * o_.zoneSectors[z]));
        return firstBin_[z] + ring * o_.zoneSectors[z] + sector;
      }
      inner = o_.zoneRadii[z];
    }
    return -1;
  }

 private:
  const GroundSegmentationOptions& o_;
  std::vector<int> firstBin_;
  int binCount_ = 0;
};

void segmentBin(std::span<const Eigen::Vector3d> points, std::vector<uint32_t>& bin,
                const GroundSegmentationOptions& o, std::vector<uint8_t>& ground) {
  if (int(bin.size()) < o.minBinPoints) return;
  std::sort(bin.begin(), bin.end(), [&](uint32_t a, uint32_t b) { return points[a].z() < points[b].z(); });
  const size_t k = std::min(bin.size(), size_t(o.seedPoints));
  double lowest = 0.0;
  for (size_t i = 0; i < k; ++i) lowest += points[bin[i]].z();
  lowest /= double(k);
  std::vector<uint32_t> members;
  for (uint32_t i : bin) {
    if (points[i].z() > lowest + o.seedHeight) break;
    members.push_back(i);
  }
  if (members.size() < 3) return;
  Plane plane;
  for (int it = 0; it < o.iterations; ++it) {
    plane = fitPlane(points, members);
    members.clear();
    for (uint32_t i : bin) {
      if (plane.distance(points[i]) < o.planeDistance) members.push_back(i);
    }
    if (members.size() < 3) return;
  }
  if (plane.normal.z() < std::cos(o.maxTiltDeg * std::numbers::pi / 180.0)) return;
  const double range = std::hypot(plane.centroid.x(), plane.centroid.y());
  if (plane.centroid.z() > o.groundZ + o.maxElevation + o.elevationPerMetre * range) return;
  for (uint32_t i : members) ground[i] = 1;
}

}  // namespace

std::vector<uint8_t> segmentGround(std::span<const Eigen::Vector3d> points, const GroundSegmentationOptions& options) {
  validate(options);
  const BinLayout layout(options);
  std::vector<std::vector<uint32_t>> bins(size_t(layout.binCount()));
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) continue;
    const int b = layout.binOf(points[i]);
    if (b >= 0) bins[size_t(b)].push_back(uint32_t(i));
  }
  std::vector<uint8_t> ground(points.size(), 0);
  for (std::vector<uint32_t>& bin : bins) segmentBin(points, bin, options, ground);
  return ground;
}

}  // namespace hdprior
