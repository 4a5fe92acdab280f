#include "engine/pipeline/pipeline_run.h"

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/session.h"

namespace hdprior {

std::unique_ptr<HdMap> loadPriorMap(const ArgoverseLog& log, const Config& config) {
  HdMapOptions options;
  options.ndtCellSizes = config.match.cellSizes;
  auto map = std::make_unique<HdMap>(HdMap::load(log.mapFiles(), options));
  if (!map->hasGroundHeight()) throw Error(log.dir().string(), "the map has no ground-height raster (the altitude prior needs it)");
  return map;
}

PipelineRun runPipeline(const ArgoverseLog& log, const Config& config, const PipelineOptions& options,
                        const std::function<void(size_t, size_t)>& progress) {
  const std::unique_ptr<HdMap> map = options.priors ? loadPriorMap(log, config) : nullptr;
  Session session(log, map.get(), config, options);
  session.run(progress);
  return session.finish(options.mapVoxel);
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
    ++(k.gated || k.match.status == MatchStatus::Rejected ? m.matches.rejected
       : k.match.status == MatchStatus::Accepted          ? m.matches.accepted
                                                          : m.matches.degenerate);
    if (k.hasPrior && run.groundTruth.covers(k.timestampNs)) {
      m.priorErrors.push_back(matchErrorSample(planarPose(run.groundTruth.at(k.timestampNs)), planarPose(k.prior.pose),
                                               marginalPlanarInformation(k.prior)));
    }
  }
  m.matches.constraints = constraintsOf(run.matches);
  m.priorCalibration = calibrateMatches(m.priorErrors);
  return m;
}

}  // namespace hdprior
