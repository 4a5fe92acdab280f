#include "engine/odom/given_odometry.h"

#include <algorithm>
#include <cstdio>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/seconds_text.h"

namespace hdprior {
namespace {

std::string milliseconds(int64_t ns) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f ms", double(ns) * 1e-6);
  return b;
}

// The sweep's time inside the file's span, or an Error saying by how much it is outside.
int64_t coveredTime(const PoseTrajectory& file, int64_t t, size_t sweep, const std::string& source) {
  const int64_t before = file.startNs() - t, after = t - file.endNs();
  if (before > kGivenOdometryToleranceNs || after > kGivenOdometryToleranceNs) {
    throw Error(source, "the poses span " + formatSecondsNs(file.startNs()) + " to " + formatSecondsNs(file.endNs()) +
                            " s but sweep " + std::to_string(sweep) + " is at " + formatSecondsNs(t) + " s, " +
                            milliseconds(std::max(before, after)) + (before > 0 ? " before the first" : " after the last") +
                            " pose (at most 1 ms allowed): the trajectory must cover every sweep");
  }
  return std::clamp(t, file.startNs(), file.endNs());
}

}  // namespace

const char* givenOdometryFrameName(GivenOdometryFrame frame) { return frame == GivenOdometryFrame::First ? "first" : "city"; }

GivenOdometryFrame parseGivenOdometryFrame(const std::string& name, const std::string& source) {
  if (name == "first") return GivenOdometryFrame::First;
  if (name == "city") return GivenOdometryFrame::City;
  throw Error(source, "must be first or city, not '" + name + "'");
}

GivenOdometry readGivenOdometry(const TrajectoryFileSpec& spec, GivenOdometryFrame frame,
                                const std::vector<int64_t>& sweepTimestampsNs) {
  TrajectoryFileContents contents = readTrajectoryFile(spec, sweepTimestampsNs);
  return {std::move(contents.trajectory), frame, spec.file.string(), contents.format};
}

PoseTrajectory givenOdometryAtSweeps(const GivenOdometry& given, const std::vector<int64_t>& sweepTimestampsNs,
                                     const SE3& cityTOdom) {
  std::vector<SE3> filePoses;
  for (size_t i = 0; i < sweepTimestampsNs.size(); ++i) {
    filePoses.push_back(given.trajectory.at(coveredTime(given.trajectory, sweepTimestampsNs[i], i, given.file)));
  }
  const SE3 odomTFile = filePoses.empty() ? SE3::Identity()
                        : given.frame == GivenOdometryFrame::First ? SE3(filePoses.front().inverse())
                                                                   : SE3(cityTOdom.inverse());
  std::vector<SE3> odomTEgo;
  for (const SE3& p : filePoses) odomTEgo.push_back(odomTFile * p);
  return PoseTrajectory(sweepTimestampsNs, std::move(odomTEgo), given.file);
}

GivenOdometry givenOdometryOf(const std::filesystem::path& file, const OdometryFileOptions& options, const ArgoverseLog& log) {
  return readGivenOdometry({file, options.format, options.times}, options.frame, log.sweepTimestamps());
}

PoseTrajectory givenOdometryInCity(const GivenOdometry& given, const ArgoverseLog& log) {
  const std::vector<int64_t>& sweeps = log.sweepTimestamps();
  if (sweeps.empty() || !log.cityTEgo().covers(sweeps.front()))
    throw Error(log.dir().string(), "the ground-truth poses do not cover the first sweep (needed to anchor the start)");
  const SE3 cityTOdom = log.cityTEgo().at(sweeps.front());
  const PoseTrajectory odomTEgo = givenOdometryAtSweeps(given, sweeps, cityTOdom);
  std::vector<SE3> cityTEgo;
  for (const SE3& pose : odomTEgo.poses()) cityTEgo.push_back(cityTOdom * pose);
  return PoseTrajectory(sweeps, std::move(cityTEgo), given.file);
}

}  // namespace hdprior
