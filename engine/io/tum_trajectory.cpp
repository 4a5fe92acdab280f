#include "engine/io/tum_trajectory.h"

#include <cmath>
#include <cstdio>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/seconds_text.h"
#include "engine/io/text_lines.h"
#include "engine/io/trajectory_checks.h"

namespace hdprior {
namespace {

constexpr const char* kTumFields[] = {"timestamp", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};

SE3 tumPose(const TextLine& line, const std::string& where) {
  double v[7];
  for (size_t i = 0; i < 7; ++i) v[i] = finiteField(line.fields[i + 1], kTumFields[i + 1], where);
  return makeSE3(checkedQuaternion(Eigen::Quaterniond(v[6], v[3], v[4], v[5]), where), Eigen::Vector3d(v[0], v[1], v[2]));
}

}  // namespace

std::string formatTum(const PoseTrajectory& trajectory) {
  std::string out = "# timestamp tx ty tz qx qy qz qw\n";
  char line[256];
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const SE3& T = trajectory.poses()[i];
    const Eigen::Quaterniond q(T.rotation());
    std::snprintf(line, sizeof line, " %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", T.translation().x(), T.translation().y(),
                  T.translation().z(), q.x(), q.y(), q.z(), q.w());
    out += formatSecondsNs(trajectory.timestamps()[i]) + line;
  }
  return out;
}

PoseTrajectory parseTum(const std::string& text, const std::string& source) {
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (const TextLine& line : dataLines(text)) {
    const std::string where = source + ":" + std::to_string(line.number);
    if (line.fields.size() != 8) {
      throw Error(where, "expected 8 fields 'timestamp tx ty tz qx qy qz qw', found " + std::to_string(line.fields.size()));
    }
    stamps.push_back(timestampField(line.fields[0], where, stamps.empty() ? nullptr : &stamps.back()));
    poses.push_back(tumPose(line, where));
  }
  return PoseTrajectory(std::move(stamps), std::move(poses), source);
}

void writeTum(const std::filesystem::path& path, const PoseTrajectory& trajectory) {
  writeFileAtomically(path, formatTum(trajectory));
}

PoseTrajectory readTum(const std::filesystem::path& path) { return parseTum(readFileText(path), path.string()); }

}  // namespace hdprior
