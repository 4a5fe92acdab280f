#include "engine/io/kitti_trajectory.h"

#include <cstdio>

#include "engine/error.h"
#include "engine/io/seconds_text.h"
#include "engine/io/text_lines.h"
#include "engine/io/trajectory_checks.h"

namespace hdprior {
namespace {

constexpr const char* kKittiFields[] = {"r11", "r12", "r13", "tx", "r21", "r22", "r23", "ty", "r31", "r32", "r33", "tz"};

SE3 kittiPose(const TextLine& line, const std::string& where) {
  double v[12];
  for (size_t i = 0; i < 12; ++i) v[i] = finiteField(line.fields[i], kKittiFields[i], where);
  Eigen::Matrix3d R;
  R << v[0], v[1], v[2], v[4], v[5], v[6], v[8], v[9], v[10];
  return makeSE3(checkedRotation(R, where), Eigen::Vector3d(v[3], v[7], v[11]));
}

}  // namespace

std::string formatKitti(const std::vector<SE3>& poses) {
  std::string out;
  char line[512];
  for (const SE3& T : poses) {
    const Eigen::Matrix3d R = T.rotation();
    const Eigen::Vector3d t = T.translation();
    std::snprintf(line, sizeof line, "%.12g %.12g %.12g %.12g %.12g %.12g %.12g %.12g %.12g %.12g %.12g %.12g\n", R(0, 0),
                  R(0, 1), R(0, 2), t.x(), R(1, 0), R(1, 1), R(1, 2), t.y(), R(2, 0), R(2, 1), R(2, 2), t.z());
    out += line;
  }
  return out;
}

std::vector<SE3> parseKitti(const std::string& text, const std::string& source) {
  std::vector<SE3> poses;
  for (const TextLine& line : dataLines(text)) {
    const std::string where = source + ":" + std::to_string(line.number);
    if (line.fields.size() != 12) {
      throw Error(where, "expected 12 fields (a 3x4 pose matrix row by row), found " + std::to_string(line.fields.size()));
    }
    poses.push_back(kittiPose(line, where));
  }
  return poses;
}

std::vector<int64_t> parseTimes(const std::string& text, const std::string& source) {
  std::vector<int64_t> stamps;
  for (const TextLine& line : dataLines(text)) {
    const std::string where = source + ":" + std::to_string(line.number);
    if (line.fields.size() != 1) throw Error(where, "expected one timestamp (seconds), found " + std::to_string(line.fields.size()) + " fields");
    stamps.push_back(timestampField(line.fields[0], where, stamps.empty() ? nullptr : &stamps.back()));
  }
  return stamps;
}

std::string formatTimes(const std::vector<int64_t>& timestampsNs) {
  std::string out;
  for (int64_t t : timestampsNs) out += formatSecondsNs(t) + "\n";
  return out;
}

PoseTrajectory kittiTrajectory(std::vector<SE3> poses, std::vector<int64_t> timestampsNs, const std::string& source,
                               const std::string& timesSource) {
  if (poses.size() != timestampsNs.size()) {
    throw Error(source, std::to_string(poses.size()) + " poses but " + std::to_string(timestampsNs.size()) + " " + timesSource +
                            " (a KITTI file has one pose per line, in order)");
  }
  return PoseTrajectory(std::move(timestampsNs), std::move(poses), source);
}

}  // namespace hdprior
