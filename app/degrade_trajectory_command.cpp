#include <cstdio>
#include <filesystem>

#include "app/command_line.h"
#include "app/commands.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/kitti_trajectory.h"
#include "engine/io/trajectory_file.h"
#include "engine/io/tum_trajectory.h"
#include "engine/odom/degraded_trajectory.h"
#include "engine/odom/odometry_drift.h"

namespace hdprior::app {
namespace {

namespace fs = std::filesystem;

// A log's ground truth at every sweep it covers, or a TUM file's poses.
PoseTrajectory sourceTrajectory(const fs::path& in) {
  if (!fs::is_directory(in)) return readTum(in);
  return ArgoverseLog(in).cityTEgoAtSweeps();
}

}  // namespace

int runDegradeTrajectory(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"out", "drift", "random-walk", "seed", "format"}, .flags = {}, .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior degrade-trajectory (LOG | FILE.tum) --out FILE [--drift SCALE,YAW_DEG_PER_100M"
                                       "[,PITCH_DEG_PER_100M]] [--random-walk SIGMA_M,SIGMA_DEG] [--seed N] [--format tum|kitti]"});
  const fs::path out = cl.required("out");
  const OdometryDrift drift = cl.value("drift") ? parseOdometryDrift(*cl.value("drift"), "option --drift") : OdometryDrift{};
  RandomWalk walk = cl.value("random-walk") ? parseRandomWalk(*cl.value("random-walk"), "option --random-walk") : RandomWalk{};
  const long long seed = cl.integer("seed", 1);
  if (seed < 0) throw Error("option --seed", "must not be negative");
  walk.seed = uint64_t(seed);
  const TrajectoryFormat format = cl.value("format")              ? parseTrajectoryFormat(*cl.value("format"), "option --format")
                                  : out.extension() == ".kitti" ? TrajectoryFormat::Kitti
                                                                  : TrajectoryFormat::Tum;
  const PoseTrajectory source = sourceTrajectory(cl.positional()[0]);
  const std::vector<SE3> degraded = degradedPoses(source.poses(), drift, walk);
  if (format == TrajectoryFormat::Kitti) writeFileAtomically(out, formatKitti(degraded));
  else writeTum(out, PoseTrajectory(source.timestamps(), degraded, out.string()));
  std::printf("wrote %s: %zu poses (%s), drift scale %g, yaw %g deg/100 m, pitch %g deg/100 m, random walk %g m, %g deg "
              "per sqrt(m), seed %llu\n",
              out.string().c_str(), degraded.size(), trajectoryFormatName(format), drift.scale, drift.yawDegPer100m,
              drift.pitchDegPer100m, walk.translationSigma, walk.rotationSigmaDeg, (unsigned long long)walk.seed);
  return 0;
}

}  // namespace hdprior::app
