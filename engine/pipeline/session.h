#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "engine/pipeline/keyframe_inspection.h"
#include "engine/pipeline/pipeline_run.h"

namespace hdprior {

class HdMap;

// One log, its map and configuration, and every stage's results so far: the one object the CLI,
// the app and the tests drive. step() advances one sweep (odometry, and at a keyframe the HD-map
// prior stage with an incremental solve); run() goes to the end with progress and cancel;
// optimize() is the batch solve on demand (with other prior and graph options if given);
// inspectKeyframe() re-runs one keyframe's road points and match with the options being tuned.
// Not thread-safe: one thread drives it at a time (the app runs it in a worker and reads it when
// the worker is done).
class Session {
 public:
  // map == nullptr or !options.priors: lidar odometry alone. options.givenOdometry: the odometry
  // takes its poses from that trajectory (givenOdometryAtSweeps). Throws Error for a log without
  // sweeps or whose poses do not cover the first sweep (the start), a map without what the priors
  // need, or a given trajectory that does not cover the sweeps.
  Session(const ArgoverseLog& log, const HdMap* map, const Config& config, const PipelineOptions& options = {});
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  const ArgoverseLog& log() const { return log_; }
  const Config& config() const { return config_; }
  bool hasPriors() const { return priors_ != nullptr; }
  // The trajectory file the odometry takes its poses from; nullopt: the built-in lidar odometry.
  const std::optional<GivenOdometry>& givenOdometry() const { return givenOdometry_; }
  size_t sweepCount() const;
  size_t sweepsDone() const { return nextSweep_; }  // skipped ones included
  bool done() const { return sweepsDone() == sweepCount(); }

  // One sweep. One that cannot be read (or has no points) is skipped and noted in skippedSweeps();
  // the odometry's next prediction spans the gap. Throws Error naming the sweep file and the share
  // when more than config.maxUnreadableSweepShare of the log's sweeps are unreadable.
  void step();
  // Sweeps until the odometry makes a keyframe, or the end.
  void stepKeyframe();
  // Until the end; progress(done, total) after each sweep. Returns false when `cancel` was set
  // (checked between sweeps; the session stays usable and can go on later).
  bool run(const std::function<void(size_t, size_t)>& progress = {}, const std::atomic<bool>* cancel = nullptr);

  // The batch solve of the graph as it stands (the final solve, or "optimise now" mid-way).
  SolveSummary optimize();
  // The same after rebuilding the graph from the keyframes and matches so far with other prior
  // and graph options (the app's PGO panel); they become the session's options.
  SolveSummary optimize(const PosePriorOptions& prior, const PoseGraphOptions& graph);

  // Keyframe k's sub-map, road points and match re-computed with these options, from `start`
  // (default: the pose the run's match started from). Changes nothing in the session.
  KeyframeInspection inspectKeyframe(size_t k, const SweepRoadPointOptions& roadPoints, const MatchOptions& match,
                                     const std::optional<Eigen::Vector3d>& start = std::nullopt) const;

  const Odometry& odometry() const { return *odometry_; }
  const SE3& cityTOdom() const { return cityTOdom_; }
  const PoseTrajectory& groundTruth() const { return groundTruth_; }  // at the sweeps the poses cover
  PoseTrajectory odometryTrajectory() const;   // city_T_ego of every sweep done
  PoseTrajectory optimizedTrajectory() const;  // the same corrected by the graph (empty without priors)
  const std::vector<KeyframeMatch>& matches() const;  // one per keyframe (empty without priors)
  std::vector<SE3> keyframePoses() const;              // the graph's (or the odometry's) keyframe poses
  const PoseGraph* graph() const;
  // The graph's options in use: after a solve, with the drift model the priors made likeliest.
  const PoseGraphOptions& graphOptions() const;
  const StageTimes& times() const { return times_; }
  const std::vector<SkippedSweep>& skippedSweeps() const { return skipped_; }
  // Odometry frames (Keyframe::frame, KeyframeMatch::frame) are the sweeps read: the log's sweep
  // index of a frame, and its sweep.
  size_t sweepOfFrame(size_t frame) const { return frameSweeps_.at(frame); }
  std::shared_ptr<const LidarSweep> frameSweep(size_t frame) const;

  // The final batch solve, the corrected trajectory and the global map: the run as `hdprior run`
  // writes it. The session is spent afterwards.
  PipelineRun finish(double mapVoxel);

 private:
  std::shared_ptr<const LidarSweep> readableSweep(size_t index);
  void anchorAt(size_t index);

  const ArgoverseLog& log_;
  const HdMap* map_;
  Config config_;
  std::optional<GivenOdometry> givenOdometry_;
  SE3 cityTOdom_;
  std::unique_ptr<Odometry> odometry_;
  std::unique_ptr<PriorStage> priors_;
  std::vector<SE3> estimate_;
  PoseTrajectory groundTruth_;
  StageTimes times_;
  size_t maxLocalMapPoints_ = 0;
  size_t nextSweep_ = 0;
  std::vector<size_t> frameSweeps_;  // the log's sweep index of each odometry frame
  std::vector<SkippedSweep> skipped_;
};

}  // namespace hdprior
