#include "engine/pipeline/prior_stage.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/graph/odometry_information.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
#include "engine/odom/odometry.h"
#include "engine/pipeline/seconds_since.h"

namespace hdprior {
namespace {

const Config& checked(const Config& config) {
  checkConfig(config);
  return config;
}

// The stage's matcher leaves the fixed prediction gate to the stage: a match outside it is still
// made a prior, which only a run of agreeing priors can let in (InnovationGate), so that an odometry
// slip of metres does not shut out the right matches after it.
MatchOptions withoutPredictionGate(MatchOptions options) {
  options.gateChi2 = 1e9;  // the largest the options allow
  return options;
}

}  // namespace

PriorStage::PriorStage(const HdMap& map, const Config& config, const SE3& cityTOdom, bool givenPoses)
    : map_(map), config_(checked(config)), cityTOdom_(cityTOdom), givenPoses_(givenPoses),
      matcher_(std::make_unique<MapMatcher>(map, withoutPredictionGate(config.match))), graph_(std::make_unique<PoseGraph>(config.graph)) {
  if (!map.hasGroundHeight()) throw Error("HD map", "has no ground-height raster (the altitude prior needs it)");
  config_.graph = odometryDriftModel(config.graph, givenPoses_);
}

PriorStage::~PriorStage() = default;

SE3 PriorStage::predictedPose(const Keyframe& keyframe) const {
  if (graph_->size() == 0) return cityTOdom_ * keyframe.odomTEgo;
  return graph_->pose(graph_->size() - 1) * keyframe.previousTThis;
}

KeyframeSweep keyframeSweep(const Odometry& odometry, size_t keyframe, const SE3& cityTOdom, const SweepOf& sweepOf) {
  const Keyframe& kf = odometry.keyframes().at(keyframe);
  return {sweepOf(kf.frame), levelRotation(cityTOdom * odometry.frames()[kf.frame].odomTEgo)};
}

bool PriorStage::gatePrior(KeyframeMatch& m) {
  const InnovationGate::Verdict v = gate_.judge(m.keyframe, m.prior, m.outsidePrediction);
  m.innovationChi2 = v.chi2;
  m.gateQuantile = v.quantile;
  m.gated = !v.admitted;
  m.beyondOdometryReach = v.beyondOdometryReach;
  m.hasPrior = v.admitted;
  if (!v.admitted) return false;
  if (driftModels_) {
    if (v.reanchored.empty()) {
      driftModels_->observe(m.prior);
    } else {
      driftModels_->restartAt(m.prior);
    }
  }
  for (size_t k : v.reanchored) {
    matches_.at(k).hasPrior = true;
    matches_.at(k).gated = false;
  }
  return !v.reanchored.empty();
}

void PriorStage::addKeyframe(const Odometry& odometry, const SweepOf& sweepOf) {
  const Keyframe& kf = odometry.keyframes().back();
  KeyframeMatch m;
  m.keyframe = odometry.keyframes().size() - 1;
  m.frame = kf.frame;
  m.timestampNs = kf.timestampNs;
  const SE3 odometryPose = cityTOdom_ * kf.odomTEgo;
  m.predicted = predictedPose(kf);
  const Matrix6d odometryInfo = odometryInformation(kf.relativeCovariance, kf.previousTThis, config_.graph);
  if (graph_->size() == 0) {
    gate_ = InnovationGate(planarPose(m.predicted), config_.graph.mapErrorLength, config_.prior.innovationGateProbability,
                           config_.prior.reanchorPriors);
    driftModels_.emplace(config_.graph, planarPose(m.predicted));
  } else {
    gate_.predict(planarPose(graph_->pose(graph_->size() - 1)), kf.previousTThis, odometryInfo);
    if (driftModels_) driftModels_->step(kf);
  }

  auto start = std::chrono::steady_clock::now();
  const KeyframeSweep sweep = keyframeSweep(odometry, odometry.keyframes().size() - 1, cityTOdom_, sweepOf);
  const PlanarRoadPoints points = sweepRoadPoints(*sweep.sweep, sweep.egoLevel, config_.roadPoints);
  times_.roadPointsS += secondsSince(start);

  start = std::chrono::steady_clock::now();
  m.match = matcher_->match(points.road, planarPose(m.predicted), points.curb);
  m.hasPrior = m.match.status != MatchStatus::Rejected;
  m.outsidePrediction = m.hasPrior && m.match.gateChi2 > config_.match.gateChi2;
  bool reanchored = false;
  if (m.hasPrior) {
    m.prior = makePosePrior(m.match, m.predicted, map_.groundHeight(), config_.prior);
    reanchored = gatePrior(m);
  }
  times_.matchS += secondsSince(start);

  start = std::chrono::steady_clock::now();
  const size_t k = graph_->addKeyframe(kf.timestampNs, odometryPose, m.predicted);
  if (k > 0) {
    graph_->addOdometry(k - 1, k, kf.previousTThis, odometryInfo);
  }
  if (m.hasPrior && !reanchored) graph_->addPrior(k, m.prior);
  matches_.push_back(std::move(m));
  if (reanchored) rebuild(odometry);  // the run's priors and this one go in, in route order (the map error field's)
  graph_->solve();
  times_.graphS += secondsSince(start);
}

SolveSummary PriorStage::finish(const Odometry& odometry) {
  const auto start = std::chrono::steady_clock::now();
  if (driftModels_) {
    const PoseGraphOptions likeliest = driftModels_->likeliest();
    if (likeliest.odometryTranslationSigmaPerM != config_.graph.odometryTranslationSigmaPerM ||
        likeliest.odometryRotationSigmaDegPerM != config_.graph.odometryRotationSigmaDegPerM ||
        likeliest.mapErrorLength != config_.graph.mapErrorLength) {
      config_.graph.odometryTranslationSigmaPerM = likeliest.odometryTranslationSigmaPerM;
      config_.graph.odometryRotationSigmaDegPerM = likeliest.odometryRotationSigmaDegPerM;
      config_.graph.mapErrorLength = likeliest.mapErrorLength;
      rebuild(odometry);
    }
  }
  const SolveSummary s = graph_->solve();
  times_.graphS += secondsSince(start);
  return s;
}

void PriorStage::rebuildGraph(const Odometry& odometry, const PosePriorOptions& prior, const PoseGraphOptions& graph) {
  PosePriorOptions keys = prior;
  checkOptionRanges("prior options", optionFields(keys));
  config_.prior = prior;
  config_.graph = odometryDriftModel(graph, givenPoses_);
  rebuild(odometry);
}

void PriorStage::rebuild(const Odometry& odometry) {
  const PosePriorOptions& prior = config_.prior;
  auto rebuilt = std::make_unique<PoseGraph>(config_.graph);
  for (size_t k = 0; k < matches_.size(); ++k) {
    const Keyframe& kf = odometry.keyframes()[k];
    rebuilt->addKeyframe(kf.timestampNs, cityTOdom_ * kf.odomTEgo, graph_->pose(k));
    if (k > 0) {
      rebuilt->addOdometry(k - 1, k, kf.previousTThis, odometryInformation(kf.relativeCovariance, kf.previousTThis, config_.graph));
    }
    KeyframeMatch& m = matches_[k];
    if (m.hasPrior) {
      m.prior = makePosePrior(m.match, m.predicted, map_.groundHeight(), prior);
      rebuilt->addPrior(k, m.prior);
    }
  }
  graph_ = std::move(rebuilt);
}

}  // namespace hdprior
