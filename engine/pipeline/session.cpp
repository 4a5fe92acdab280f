#include "engine/pipeline/session.h"

#include <chrono>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
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

std::vector<SubmapLabel> pointLabels(const LabelledSubmap& submap) {
  std::vector<SubmapLabel> labels(submap.points.size(), SubmapLabel::Other);
  for (size_t i = 0; i < labels.size(); ++i) {
    if (submap.road[i] == kCurbPoint) labels[i] = SubmapLabel::Curb;
    else if (submap.road[i] == kRoadPoint) labels[i] = SubmapLabel::Road;
    else if (submap.ground[i]) labels[i] = SubmapLabel::Ground;
  }
  return labels;
}

}  // namespace

Session::Session(const ArgoverseLog& log, const HdMap* map, const Config& config, const PipelineOptions& options)
    : log_(log), map_(options.priors ? map : nullptr), config_(config), givenOdometry_(options.givenOdometry) {
  checkLog(log);
  cityTOdom_ = log.cityTEgo().at(log.sweepTimestamps().front());
  odometry_ = std::make_unique<Odometry>(
      config.odometry, config.keyframes,
      givenOdometry_ ? givenOdometryAtSweeps(*givenOdometry_, log.sweepTimestamps(), cityTOdom_) : PoseTrajectory{});
  if (map_) priors_ = std::make_unique<PriorStage>(*map_, config, cityTOdom_, givenOdometry_.has_value());
  groundTruth_ = groundTruthAt(log);
}

Session::~Session() = default;

size_t Session::sweepCount() const { return log_.sweepCount(); }

void Session::step() {
  if (done()) return;
  const size_t i = sweepsDone();
  const auto start = Clock::now();
  const auto sweep = log_.sweep(i);
  if (sweep->points.empty()) throw Error(log_.sweepPath(i).string(), "the sweep has zero points");
  const auto odometryStart = Clock::now();
  const OdometryFrame& frame = odometry_->registerSweep(*sweep);
  times_.odometryS += secondsSince(odometryStart);
  estimate_.push_back(cityTOdom_ * frame.odomTEgo);
  if (priors_ && odometry_->keyframes().back().frame == i) {
    priors_->addKeyframe(*odometry_, [this](size_t f) { return log_.sweep(f); });
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
  const SolveSummary s = priors_->finish();
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
  out.frame = kf.frame;
  out.timestampNs = kf.timestampNs;
  out.keyframePose = keyframePoses()[k];
  if (log_.cityTEgo().covers(kf.timestampNs)) out.truth = planarPose(log_.cityTEgo().at(kf.timestampNs));
  const bool matched = priors_ && k < priors_->matches().size();
  out.start = start ? *start : matched ? planarPose(priors_->matches()[k].predicted) : planarPose(cityTOdom_ * kf.odomTEgo);

  const KeyframeSweeps sweeps =
      keyframeSweeps(*odometry_, k, cityTOdom_, config_.submapRoadPoints, [this](size_t f) { return log_.sweep(f); });
  const LabelledSubmap submap = labelSubmap(sweeps.placed, roadPoints);
  const PlanarRoadPoints planar = planarRoadPoints(submap, roadPoints.thinCell);
  out.points.reserve(submap.points.size());
  for (const Eigen::Vector3d& p : submap.points) out.points.push_back(p.cast<float>());
  out.labels = pointLabels(submap);
  out.roadPoints = planar.road;
  out.curbPoints = planar.curb;
  MapMatcher matcher(*map_, match);
  out.match = matcher.match(out.roadPoints, out.start, out.curbPoints);
  return out;
}

PoseTrajectory Session::odometryTrajectory() const {
  const auto& stamps = log_.sweepTimestamps();
  return PoseTrajectory(std::vector<int64_t>(stamps.begin(), stamps.begin() + long(estimate_.size())), estimate_, "odometry");
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

PipelineRun Session::finish(double mapVoxel) {
  PipelineRun run;
  run.cityTOdom = cityTOdom_;
  run.groundTruth = groundTruth_;
  run.estimate = odometryTrajectory();
  run.odometryDrift = config_.odometry.drift;
  run.givenOdometry = givenOdometry_;
  if (priors_) {
    run.graphOptions = priors_->graphOptions();
    run.finalSolve = optimize();
    run.optimized = optimizedTrajectory();
    run.optimizedKeyframes = priors_->graph().poses();
    for (size_t k = 0; k < priors_->graph().size(); ++k) run.odometryScales.push_back(priors_->graph().odometryScale(k));
    run.matches = priors_->matches();
  }
  run.times = times_;
  run.maxLocalMapPoints = maxLocalMapPoints_;
  const auto mapStart = Clock::now();
  GlobalMap global = buildGlobalMap(log_, *odometry_, run.final(), mapVoxel);
  run.mapPoints = std::move(global.points);
  run.mapIntensity = std::move(global.intensity);
  run.times.mapS = secondsSince(mapStart);
  run.odometry = std::move(odometry_);
  return run;
}

}  // namespace hdprior
