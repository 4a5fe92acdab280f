#include "engine/match/map_matcher.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "engine/error.h"
#include "engine/map/hd_map.h"
#include "engine/match/curb_refinement.h"
#include "engine/match/match_assessment.h"
#include "engine/match/match_uncertainty.h"
#include "engine/match/ndt_optimizer.h"
#include "engine/match/pcl_ndt_backend.h"
#include "engine/match/stale_regions.h"

namespace hdprior {
namespace {

void validate(const MatchOptions& o) {
  const auto bad = [](const std::string& why) { throw Error("match options", why); };
  if (o.cellSizes.empty()) bad("cellSizes is empty");
  if (!(o.outlierRatio > 0 && o.outlierRatio < 1)) bad("outlierRatio must be in (0, 1)");
  if (o.maxIterations < 1 || !(o.maxStepCells > 0) || !(o.maxStepYawDeg > 0) || !(o.maxStepGain >= 1)) {
    bad("iterations or step bounds out of range");
  }
  if (!(o.translationTolerance > 0) || !(o.yawToleranceDeg > 0) || !(o.timeBudgetMs > 0)) bad("tolerances or time budget out of range");
  if (!(o.yawLength > 0) || !(o.degenerateRatio >= 0 && o.degenerateRatio < 1) || !(o.minInformation >= 0) ||
      !(o.boundaryBand > 0) || !(o.minBoundaryPoints >= 0)) {
    bad("yawLength, boundaryBand, degenerateRatio, minBoundaryPoints or minInformation out of range");
  }
  if (!(o.evidenceShare >= 0 && o.evidenceShare < 1) || o.evidenceMinPoints < 0 || o.evidenceStride < 1 ||
      !(o.evidenceMaxOffset > 0) || !(o.evidenceMaxYawDeg > 0) || !(o.evidenceKappa > 0) || !(o.staleRegionSize > 0) || !(o.staleDistance > 0) || !(o.staleDistancePerMetre >= 0) ||
      !(o.staleShare >= 0 && o.staleShare <= 1) || !(o.evidenceCurbBand > 0) ||
      !(o.evidenceCurbShare >= 0 && o.evidenceCurbShare < 1) || !(o.mapSigma >= 0) ||
      !(o.mapSigmaYawDeg >= 0) || !(o.maxSigmaAlong > 0) || !(o.maxSigmaLateral > 0) || !(o.maxSigmaYawDeg > 0)) {
    bad("evidence uncertainty options out of range");
  }
  if (o.minPoints < 1 || !(o.minInlierRatio >= 0 && o.minInlierRatio <= 1) || !(o.gateChi2 > 0) ||
      !(o.predictionSigma.minCoeff() > 0)) {
    bad("minPoints, minInlierRatio, gateChi2 or predictionSigma out of range");
  }
}

}  // namespace

MapMatcher::MapMatcher(const HdMap& map, MatchOptions options) : map_(map), options_(std::move(options)) {
  validate(options_);
  std::vector<double> sizes = options_.cellSizes;
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  for (double size : sizes) levels_.push_back(&map_.ndtGrid(size));
  if (!map_.hasBoundaryDistance()) throw Error("match options", "the map was loaded without its boundary distance field");
  if (options_.backend == MatchBackend::PclNdt) pcl_ = std::make_unique<PclNdtBackend>(map_.drivable(), options_);
}

MapMatcher::~MapMatcher() = default;

MatchResult MapMatcher::match(std::span<const Eigen::Vector2d> roadPoints, const Eigen::Vector3d& initial,
                              std::span<const Eigen::Vector2d> curbs) {
  const auto start = std::chrono::steady_clock::now();
  const RegionSelection selection = pointsInAgreeingRegions(map_.boundaryDistance(), roadPoints, curbs, initial, options_);
  const std::span<const Eigen::Vector2d> points = selection.road, curbPoints = selection.curbs;
  const auto deadline = start + std::chrono::microseconds(int64_t(options_.timeBudgetMs * 1000.0));
  MatchResult r;
  r.initial = initial;
  r.points = points.size();
  r.curbPoints = curbPoints.size();
  r.staleRegionPoints = selection.droppedPoints;
  bool timedOut = false;
  if (points.size() >= size_t(options_.minPoints)) {
    if (pcl_) {
      const PclNdtBackend::Alignment a = pcl_->align(points, initial);
      r.estimate = a.pose;
      r.iterations = a.iterations;
      r.path = {initial, a.pose};
      timedOut = std::chrono::steady_clock::now() > deadline;
    } else {
      const NdtOptimization opt = optimizeNdt(levels_, points, initial, options_, deadline);
      r.estimate = opt.pose;
      r.iterations = opt.iterations;
      r.path = opt.path;
      timedOut = opt.timedOut;
    }
    if (!timedOut) {
      const CurbRefinementOptions co{.huber = options_.curbHuber, .maxDistance = options_.curbMaxDistance,
                                     .minPoints = options_.minCurbPoints};
      const CurbRefinement c = refineOnCurbs(map_.boundaryDistance(), curbPoints, r.estimate, co);
      if (c.pose != r.estimate) r.path.push_back(c.pose);
      r.estimate = c.pose;
      r.iterations += c.iterations;
    }
  } else {
    r.estimate = initial;
    r.path = {initial};
  }
  assessMatch(*levels_.back(), map_.drivable(), map_.boundaryDistance(), points, options_, timedOut, r);
  if (r.status != MatchStatus::Rejected) {
    widenToEvidence(plausibleHalfWidths(map_.boundaryDistance(), points, curbPoints, r.estimate, options_), options_, r);
  }
  r.timeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace hdprior
