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

// The keys against their declared ranges, and the fixed internal constants.
void validate(const MatchOptions& o) {
  MatchOptions keys = o;
  checkOptionRanges("match options", optionFields(keys));
  if (!(o.maxStepCells > 0) || !(o.maxStepYawDeg > 0) || !(o.maxStepGain >= 1) || !(o.translationTolerance > 0) ||
      !(o.yawToleranceDeg > 0) || !(o.yawLength > 0)) {
    throw Error("match options", "step bounds, tolerances or yawLength out of range");
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
