#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/option_checks.h"
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

struct DegradeArguments {
  std::string in, out, drift, randomWalk, format;
  long long seed = 1;
};

int runDegradeTrajectory(const DegradeArguments& a) {
  const fs::path out = a.out;
  const OdometryDrift drift = a.drift.empty() ? OdometryDrift{} : parseOdometryDrift(a.drift, "option --drift");
  RandomWalk walk = a.randomWalk.empty() ? RandomWalk{} : parseRandomWalk(a.randomWalk, "option --random-walk");
  walk.seed = uint64_t(a.seed);
  const TrajectoryFormat format = !a.format.empty()              ? parseTrajectoryFormat(a.format, "option --format")
                                  : out.extension() == ".kitti" ? TrajectoryFormat::Kitti
                                                                  : TrajectoryFormat::Tum;
  const PoseTrajectory source = sourceTrajectory(a.in);
  const std::vector<SE3> degraded = degradedPoses(source.poses(), drift, walk);
  if (format == TrajectoryFormat::Kitti) writeFileAtomically(out, formatKitti(degraded));
  else writeTum(out, PoseTrajectory(source.timestamps(), degraded, out.string()));
  std::printf("wrote %s: %zu poses (%s), drift scale %g, yaw %g deg/100 m, pitch %g deg/100 m, random walk %g m, %g deg "
              "per sqrt(m), seed %llu\n",
              out.string().c_str(), degraded.size(), trajectoryFormatName(format), drift.scale, drift.yawDegPer100m,
              drift.pitchDegPer100m, walk.translationSigma, walk.rotationSigmaDeg, (unsigned long long)walk.seed);
  return 0;
}

}  // namespace

Command addDegradeTrajectoryCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "degrade-trajectory", "a log's ground truth at every sweep (or a TUM file's poses) degraded as another system's odometry "
                            "would be: drift, then a seeded random walk");
  auto a = std::make_shared<DegradeArguments>();
  command->add_option("SOURCE", a->in, "a log's folder or a TUM file")->type_name("LOG|FILE.tum")->required();
  command->add_option("--out", a->out, "the trajectory file to write")->type_name("FILE")->required();
  command->add_option("--drift", a->drift, "scale error, yaw and pitch drift in degrees per 100 m (default: none)")
      ->type_name("SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M]")
      ->check(parsedBy([](const std::string& text) { parseOdometryDrift(text, "option --drift"); }));
  command->add_option("--random-walk", a->randomWalk, "per axis sigma * sqrt(step length), metres and degrees per sqrt(metre) (default: none)")
      ->type_name("SIGMA_M,SIGMA_DEG")
      ->check(parsedBy([](const std::string& text) { parseRandomWalk(text, "option --random-walk"); }));
  command->add_option("--seed", a->seed, "the random walk's seed")->type_name("N")->check(integerAtLeast(0));
  command->add_option("--format", a->format, "the output's format (default: kitti for a .kitti file, else tum)")
      ->type_name("tum|kitti")
      ->check(parsedBy([](const std::string& text) { parseTrajectoryFormat(text, "option --format"); }));
  return {command, [a] { return runDegradeTrajectory(*a); }};
}

}  // namespace hdprior::app
