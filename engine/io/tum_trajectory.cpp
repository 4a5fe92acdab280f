#include "engine/io/tum_trajectory.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "engine/error.h"
#include "engine/io/file_bytes.h"

namespace hdprior {
namespace {

// Seconds text to ns without going through a double: "1234.000000005" -> 1234000000005.
int64_t parseSeconds(const std::string& s, const std::string& where) {
  const size_t dot = s.find('.');
  const std::string whole = s.substr(0, dot), frac = dot == std::string::npos ? "" : s.substr(dot + 1);
  auto digits = [](const std::string& d) { return !d.empty() && d.find_first_not_of("0123456789") == std::string::npos; };
  if (!digits(whole) || (!frac.empty() && !digits(frac)) || whole.size() > 10) throw Error(where, "bad timestamp '" + s + "'");
  int64_t ns = std::stoll(whole) * 1000000000LL;
  std::string nine = frac.substr(0, std::min<size_t>(9, frac.size()));
  nine.resize(9, '0');
  return ns + std::stoll(nine);
}

}  // namespace

std::string formatTum(const PoseTrajectory& trajectory) {
  std::string out = "# timestamp tx ty tz qx qy qz qw\n";
  char line[256];
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const int64_t t = trajectory.timestamps()[i];
    const SE3& T = trajectory.poses()[i];
    const Eigen::Quaterniond q(T.rotation());
    std::snprintf(line, sizeof line, "%" PRId64 ".%09" PRId64 " %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", t / 1000000000,
                  t % 1000000000, T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(), q.z(), q.w());
    out += line;
  }
  return out;
}

PoseTrajectory parseTum(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    std::string stamp;
    double v[7];
    fields >> stamp;
    for (double& x : v) fields >> x;
    const std::string where = source + ":" + std::to_string(number);
    if (!fields || stamp.empty()) throw Error(where, "expected 'timestamp tx ty tz qx qy qz qw'");
    for (double x : v) {
      if (!std::isfinite(x)) throw Error(where, "non-finite value");
    }
    const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
    if (std::abs(q.norm() - 1.0) > 1e-3) throw Error(where, "quaternion is not unit length");
    stamps.push_back(parseSeconds(stamp, where));
    poses.push_back(makeSE3(q, Eigen::Vector3d(v[0], v[1], v[2])));
  }
  return PoseTrajectory(std::move(stamps), std::move(poses), source);
}

void writeTum(const std::filesystem::path& path, const PoseTrajectory& trajectory) {
  writeFileAtomically(path, formatTum(trajectory));
}

PoseTrajectory readTum(const std::filesystem::path& path) { return parseTum(readFileText(path), path.string()); }

}  // namespace hdprior
