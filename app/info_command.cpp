#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/npy.h"
#include "engine/io/sim2.h"
#include "engine/io/vector_map.h"

namespace hdprior::app {

namespace {

int runInfo(const std::string& logDir) {
  const ArgoverseLog log(logDir);
  const VectorMap map = readVectorMap(log.mapFiles().vectorMap);
  const NpyArray height = readNpy(log.mapFiles().groundHeight);
  const Sim2 sim2 = readSim2(log.mapFiles().sim2);
  const PoseTrajectory& poses = log.cityTEgo();

  std::printf("log id:            %s\n", log.id().c_str());
  std::printf("city:              %s\n", log.city().c_str());
  std::printf("sweeps:            %zu\n", log.sweepCount());
  if (log.sweepCount() > 0) {
    const auto& t = log.sweepTimestamps();
    std::printf("sweep time span:   %lld .. %lld ns (%.3f s)\n", (long long)t.front(), (long long)t.back(),
                double(t.back() - t.front()) * 1e-9);
  }
  const double poseSpan = double(poses.endNs() - poses.startNs()) * 1e-9;
  std::printf("poses:             %zu over %.3f s (%.1f Hz)\n", poses.size(), poseSpan,
              poseSpan > 0 ? double(poses.size() - 1) / poseSpan : 0.0);
  std::printf("drivable areas:    %zu\n", map.drivableAreas.size());
  std::printf("lane segments:     %zu\n", map.laneSegments.size());
  std::printf("ped. crossings:    %zu\n", map.pedestrianCrossings.size());
  if (height.shape.size() != 2) throw Error(log.mapFiles().groundHeight.string(), "ground-height raster is not 2-D");
  std::printf("ground height:     %zu rows x %zu cols, %.3f m cells\n", height.shape[0], height.shape[1], 1.0 / sim2.s);
  if (log.sweepCount() > 0) std::printf("first sweep:       %zu points\n", log.sweep(0)->points.size());
  return 0;
}

}  // namespace

Command addInfoCommand(CLI::App& hdprior) {
  CLI::App* info = hdprior.add_subcommand("info", "summarise an Argoverse 2 log: id, city, sweeps, poses, map elements, "
                                                  "ground-height raster, the first sweep's points");
  auto log = std::make_shared<std::string>();
  addLogArgument(*info, *log);
  return {info, [log] { return runInfo(*log); }};
}

}  // namespace hdprior::app
