#include "engine/pipeline/session.h"

#include <chrono>
#include <cstdio>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
#include "engine/pipeline/global_map.h"
#include "engine/pipeline/point_labels.h"
#include "engine/pipeline/seconds_since.h"

namespace hdprior {
namespace {

using Clock = std::chrono::steady_clock;

void checkLog(const ArgoverseLog& log) {
  if (log.sweepCount() == 0) throw Error((log.dir() / "sensors" / "lidar").string(), "the log has no sweeps");
  if (!log.cityTEgo().covers(log.sweepTimestamps().front())) {
    throw Error(log.dir().string(), "the ground-truth poses do not cover the first sweep (needed to anchor the start)");
  }
}

}  // namespace

Session::Session(const ArgoverseLog& log, const HdMap* map, const Config& config, const PipelineOptions& options)
    : log_(log), map_(options.priors ? map : nullptr), config_(config), givenOdometry_(options.givenOdometry) {
  checkConfig(config);
  checkLog(log);
  cityTOdom_ = log.cityTEgo().at(log.sweepTimestamps().front());
  odometry_ = std::make_unique<Odometry>(
      config.odometry, config.keyframes,
      givenOdometry_ ? givenOdometryAtSweeps(*givenOdometry_, log.sweepTimestamps(), cityTOdom_) : PoseTrajectory{});
  if (map_) priors_ = std::make_unique<PriorStage>(*map_, config, cityTOdom_, givenOdometry_.has_value());
  groundTruth_ = log.cityTEgoAtSweeps();
}

Session::~Session() = default;

size_t Session::sweepCount() const { return log_.sweepCount(); }

std::shared_ptr<const LidarSweep> Session::frameSweep(size_t frame) const { return log_.sweep(frameSweeps_.at(frame)); }

// The sweep, or nullptr when it is skipped.
std::shared_ptr<const LidarSweep> Session::readableSweep(size_t index) {
  const std::filesystem::path file = log_.sweepPath(index);
  std::string problem;
  try {
    std::shared_ptr<const LidarSweep> sweep = log_.sweep(index);
    if (!sweep->points.empty()) return sweep;
    problem = "the sweep has zero points";
  } catch (const Error& e) {
    problem = e.file() == file.string() ? e.reason() : e.what();
  }
  skipped_.push_back({index, file, problem});
  const double share = double(skipped_.size()) / double(sweepCount());
  if (share > config_.maxUnreadableSweepShare) {
    char text[160];
    std::snprintf(text, sizeof text, "; %zu of the log's %zu sweeps (%.1f %%) are unreadable, more than %g %% "
                  "(config sweeps.max_unreadable_share)", skipped_.size(), sweepCount(), 100.0 * share,
                  100.0 * config_.maxUnreadableSweepShare);
    throw Error(file.string(), problem + text);
  }
  return nullptr;
}

// The built-in odometry starts at the first sweep it can read: its frame and the graph are anchored
// at that sweep's ground-truth pose. (Given poses keep the first sweep's frame: the file covers it.)
void Session::anchorAt(size_t index) {
  const int64_t t = log_.sweepTimestamps()[index];
  if (!log_.cityTEgo().covers(t)) {
    throw Error(log_.dir().string(), "the ground-truth poses do not cover the first readable sweep (needed to anchor the start)");
  }
  cityTOdom_ = log_.cityTEgo().at(t);
  if (map_) priors_ = std::make_unique<PriorStage>(*map_, config_, cityTOdom_, givenOdometry_.has_value());
}

void Session::step() {
  if (done()) return;
  const size_t i = nextSweep_++;
  const auto start = Clock::now();
  const std::shared_ptr<const LidarSweep> sweep = readableSweep(i);
  if (!sweep) {
    if (done() && frameSweeps_.empty()) throw Error((log_.dir() / "sensors" / "lidar").string(), "no sweep of the log can be read");
    times_.pipelineS += secondsSince(start);
    return;
  }
  if (frameSweeps_.empty() && i > 0 && !odometry_->givenPoses()) anchorAt(i);
  const auto odometryStart = Clock::now();
  const OdometryFrame& frame = odometry_->registerSweep(*sweep);
  times_.odometryS += secondsSince(odometryStart);
  frameSweeps_.push_back(i);
  estimate_.push_back(cityTOdom_ * frame.odomTEgo);
  if (priors_ && odometry_->keyframes().back().frame + 1 == odometry_->frames().size()) {
    priors_->addKeyframe(*odometry_, [this](size_t f) { return frameSweep(f); });
    times_.roadPointsS = priors_->times().roadPointsS;
    times_.matchS = priors_->times().matchS;
    times_.graphS = priors_->times().graphS;
  }
  maxLocalMapPoints_ = std::max(maxLocalMapPoints_, odometry_->localMapPoints());
  times_.pipelineS += secondsSince(start);
}

void Session::stepKeyframe() {
  const size_t keyframes = odometry_->keyframes().size();
  while (!done() && odometry_->keyframes().size() == keyframes) step();
}

bool Session::run(const std::function<void(size_t, size_t)>& progress, const std::atomic<bool>* cancel) {
  while (!done()) {
    if (cancel && cancel->load()) return false;
    step();
    if (progress) progress(sweepsDone(), sweepCount());
  }
  return true;
}

SolveSummary Session::optimize() {
  if (!priors_) return {};
  const auto start = Clock::now();
  const SolveSummary s = priors_->finish(*odometry_);
  times_.graphS = priors_->times().graphS;
  times_.pipelineS += secondsSince(start);
  return s;
}

SolveSummary Session::optimize(const PosePriorOptions& prior, const PoseGraphOptions& graph) {
  config_.prior = prior;
  config_.graph = graph;
  if (!priors_) return {};
  priors_->rebuildGraph(*odometry_, prior, graph);
  return optimize();
}

KeyframeInspection Session::inspectKeyframe(size_t k, const SweepRoadPointOptions& roadPoints, const MatchOptions& match,
                                            const std::optional<Eigen::Vector3d>& start) const {
  if (k >= odometry_->keyframes().size()) {
    throw Error("keyframe " + std::to_string(k), "out of range: the session has " +
                                                     std::to_string(odometry_->keyframes().size()) + " keyframes");
  }
  if (!map_) throw Error("keyframe " + std::to_string(k), "the session runs without HD-map priors (no map to match)");
  const Keyframe& kf = odometry_->keyframes()[k];
  KeyframeInspection out;
  out.keyframe = k;
  out.frame = sweepOfFrame(kf.frame);
  out.timestampNs = kf.timestampNs;
  out.keyframePose = keyframePoses()[k];
  if (log_.cityTEgo().covers(kf.timestampNs)) out.truth = planarPose(log_.cityTEgo().at(kf.timestampNs));
  const bool matched = priors_ && k < priors_->matches().size();
  out.start = start ? *start : matched ? planarPose(priors_->matches()[k].predicted) : planarPose(cityTOdom_ * kf.odomTEgo);

  const KeyframeSweep sweep = keyframeSweep(*odometry_, k, cityTOdom_, [this](size_t f) { return frameSweep(f); });
  const LabelledSweep labelled = labelSweep(*sweep.sweep, sweep.egoLevel, roadPoints);
  const PlanarRoadPoints planar = planarRoadPoints(labelled, roadPoints.thinCell);
  out.points.reserve(labelled.points.size());
  for (const Eigen::Vector3d& p : labelled.points) out.points.push_back(p.cast<float>());
  out.labels = pointLabels(labelled);
  out.roadPoints = planar.road;
  out.curbPoints = planar.curb;
  MapMatcher matcher(*map_, match);
  out.match = matcher.match(out.roadPoints, out.start, out.curbPoints);
  return out;
}

PoseTrajectory Session::odometryTrajectory() const {
  std::vector<int64_t> stamps;
  for (size_t s : frameSweeps_) stamps.push_back(log_.sweepTimestamps()[s]);
  return PoseTrajectory(stamps, estimate_, "odometry");
}

PoseTrajectory Session::optimizedTrajectory() const {
  if (!priors_ || priors_->graph().size() == 0) return {};
  return priors_->graph().correct(odometryTrajectory());
}

const std::vector<KeyframeMatch>& Session::matches() const {
  static const std::vector<KeyframeMatch> none;
  return priors_ ? priors_->matches() : none;
}

std::vector<SE3> Session::keyframePoses() const {
  if (priors_) return priors_->graph().poses();
  std::vector<SE3> poses;
  for (const Keyframe& kf : odometry_->keyframes()) poses.push_back(cityTOdom_ * kf.odomTEgo);
  return poses;
}

const PoseGraph* Session::graph() const { return priors_ ? &priors_->graph() : nullptr; }

const PoseGraphOptions& Session::graphOptions() const { return priors_ ? priors_->graphOptions() : config_.graph; }

PipelineRun Session::finish(double mapVoxel) {
  PipelineRun run;
  run.cityTOdom = cityTOdom_;
  run.groundTruth = groundTruth_;
  run.estimate = odometryTrajectory();
  run.odometryDrift = config_.odometry.drift;
  run.givenOdometry = givenOdometry_;
  if (priors_) {
    run.finalSolve = optimize();
    run.graphOptions = priors_->graphOptions();  // after the solve: the drift model it estimated
    run.driftModelCandidates = priors_->driftModelCandidates();
    run.optimized = optimizedTrajectory();
    run.optimizedKeyframes = priors_->graph().poses();
    run.matches = priors_->matches();
  }
  run.times = times_;
  run.maxLocalMapPoints = maxLocalMapPoints_;
  run.skippedSweeps = skipped_;
  run.frameSweeps = frameSweeps_;
  const auto mapStart = Clock::now();
  GlobalMap global = buildGlobalMap([this](size_t f) { return frameSweep(f); }, *odometry_, run.final(), mapVoxel);
  run.mapPoints = std::move(global.points);
  run.mapIntensity = std::move(global.intensity);
  run.times.mapS = secondsSince(mapStart);
  run.odometry = std::move(odometry_);
  return run;
}

}  // namespace hdprior
