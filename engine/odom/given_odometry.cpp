#include "engine/odom/given_odometry.h"

#include <algorithm>
#include <cstdio>

#include "engine/error.h"
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

}  // namespace hdprior
