#include "engine/pipeline/pipeline_run.h"

#include <chrono>

#include "engine/error.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/global_map.h"

namespace hdprior {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void checkLog(const ArgoverseLog& log) {
  if (log.sweepCount() == 0) throw Error((log.dir() / "sensors" / "lidar").string(), "the log has no sweeps");
  if (!log.cityTEgo().covers(log.sweepTimestamps().front())) {
    throw Error(log.dir().string(), "the ground-truth poses do not cover the first sweep (needed to anchor the start)");
  }
}

std::unique_ptr<HdMap> loadPriorMap(const ArgoverseLog& log, const Config& config) {
  HdMapOptions options;
  options.ndtCellSizes = config.match.cellSizes;
  auto map = std::make_unique<HdMap>(HdMap::load(log.mapFiles(), options));
  if (!map->hasGroundHeight()) throw Error(log.dir().string(), "the map has no ground-height raster (the altitude prior needs it)");
  return map;
}

PoseTrajectory groundTruthAt(const ArgoverseLog& log) {
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int64_t t : log.sweepTimestamps()) {
    if (!log.cityTEgo().covers(t)) continue;
    stamps.push_back(t);
    poses.push_back(log.cityTEgo().at(t));
  }
  return PoseTrajectory(stamps, poses, (log.dir() / "city_SE3_egovehicle.feather").string());
}

}  // namespace

PipelineRun runPipeline(const ArgoverseLog& log, const Config& config, const PipelineOptions& options,
                        const std::function<void(size_t, size_t)>& progress) {
  checkLog(log);
  const size_t n = log.sweepCount();
  const auto& stamps = log.sweepTimestamps();
  PipelineRun run;
  run.odometry = std::make_unique<Odometry>(config.odometry, config.keyframes);
  run.cityTOdom = log.cityTEgo().at(stamps.front());
  const std::unique_ptr<HdMap> map = options.priors ? loadPriorMap(log, config) : nullptr;
  std::unique_ptr<PriorStage> priors = map ? std::make_unique<PriorStage>(*map, config, run.cityTOdom) : nullptr;
  const auto sweepOf = [&](size_t i) { return log.sweep(i); };

  std::vector<SE3> estimate;
  const auto start = Clock::now();
  for (size_t i = 0; i < n; ++i) {
    const auto sweep = log.sweep(i);
    if (sweep->points.empty()) throw Error(log.sweepPath(i).string(), "the sweep has zero points");
    const auto odometryStart = Clock::now();
    const OdometryFrame& frame = run.odometry->registerSweep(*sweep);
    run.times.odometryS += secondsSince(odometryStart);
    estimate.push_back(run.cityTOdom * frame.odomTEgo);
    if (priors && run.odometry->keyframes().back().frame == i) priors->addKeyframe(*run.odometry, sweepOf);
    run.maxLocalMapPoints = std::max(run.maxLocalMapPoints, run.odometry->localMapPoints());
    if (progress) progress(i + 1, n);
  }
  run.estimate = PoseTrajectory(stamps, estimate, "odometry");
  if (priors) {
    run.finalSolve = priors->finish();
    run.optimized = priors->graph().correct(run.estimate);
    run.optimizedKeyframes = priors->graph().poses();
    run.matches = priors->matches();
    run.times.roadPointsS = priors->times().roadPointsS;
    run.times.matchS = priors->times().matchS;
    run.times.graphS = priors->times().graphS;
  }
  run.times.pipelineS = secondsSince(start);
  run.groundTruth = groundTruthAt(log);

  const auto mapStart = Clock::now();
  GlobalMap global = buildGlobalMap(log, *run.odometry, run.final(), options.mapVoxel);
  run.mapPoints = std::move(global.points);
  run.mapIntensity = std::move(global.intensity);
  run.times.mapS = secondsSince(mapStart);
  return run;
}

RunMetrics evaluateRun(const PipelineRun& run) {
  RunMetrics m;
  m.odometry = evaluateTrajectory(run.groundTruth, run.estimate, AlignmentMode::None);
  if (run.hasPriors()) m.optimized = evaluateTrajectory(run.groundTruth, run.optimized, AlignmentMode::None);
  if (run.estimate.size() >= 3) {
    for (AlignmentMode mode : {AlignmentMode::SE3, AlignmentMode::Sim3, AlignmentMode::FourDof}) {
      m.odometryAligned.push_back(evaluateTrajectory(run.groundTruth, run.estimate, mode));
    }
  }
  for (const KeyframeMatch& k : run.matches) {
    ++(k.match.status == MatchStatus::Accepted ? m.matches.accepted
       : k.match.status == MatchStatus::Degenerate ? m.matches.degenerate
                                                   : m.matches.rejected);
  }
  return m;
}

}  // namespace hdprior
