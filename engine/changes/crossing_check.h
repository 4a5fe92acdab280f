#pragma once
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/changes/map_verdict.h"
#include "engine/changes/sweep_paint.h"
#include "engine/geom/se3.h"
#include "engine/io/vector_map.h"

namespace hdprior {

// A pedestrian crossing of the map, judged by the paint the lidar saw inside it.
struct CrossingVerdict {
  int64_t id = 0;
  std::vector<Eigen::Vector2d> outline;  // edge1, then edge2 backwards (city x, y)
  MapVerdict verdict = MapVerdict::Unobserved;
  double confidence = 0.0;
  int roadPoints = 0, paintRuns = 0;  // near the sensor, inside the outline
  int firstFrame = -1, bestFrame = -1;  // the first frame with road points inside; the one with most paint (or road points)
};

// Paint across the road where the map has no crossing and no painted lane line.
struct MissingCrossing {
  std::vector<Eigen::Vector2d> outline;  // a rectangle around the paint, counter-clockwise
  double confidence = 0.0;
  int paintRuns = 0;
  int firstFrame = -1, bestFrame = -1;
};

// The paint evidence of a log's sweeps against its map's crossings and lane lines.
//
// A crossing is painted (consistent) or not (contradicted) by the likelihood ratio of its paint
// runs under two Poisson rates per road point near the sensor: options.crossingPaintRate (a
// painted crossing) against options.asphaltPaintRate (plain asphalt); too few road points to
// tell leave it unobserved; runs on a painted lane line through it are not its paint. Runs outside
// every crossing and off every painted lane line that gather into a patch
// options.missingCrossingExtent deep and wide, its long side across the lanes, are a missing crossing.
class CrossingEvidence {
 public:
  CrossingEvidence(const VectorMap& map, const ChangeOptions& options);

  // A sweep's paint (findSweepPaint) at city_T_ego.
  void add(int frame, const SweepPaint& paint, const SE3& cityTEgo);

  std::vector<CrossingVerdict> verdicts() const;
  std::vector<MissingCrossing> missing() const;

 private:
  struct Crossing {
    CrossingVerdict verdict;
    std::vector<Eigen::Vector2d> reach;     // the outline grown by half a metre: paint at the mapped edge counts
    std::vector<Eigen::Vector2d> explains;  // grown by a metre: paint here is the crossing's, never a missing one
    int bestFrameRuns = -1, bestFrameRoadPoints = -1;
  };
  struct StrayRun {
    Eigen::Vector2d city;
    int frame;
  };
  bool onPaintedLine(const Eigen::Vector2d& city) const;
  // The direction of the lane boundary nearest to a point (within 15 m).
  std::optional<Eigen::Vector2d> laneDirectionAt(const Eigen::Vector2d& city) const;
  int roadPointsIn(const std::vector<Eigen::Vector2d>& outline) const;

  ChangeOptions options_;
  std::vector<Crossing> crossings_;
  std::vector<std::vector<Eigen::Vector2d>> paintedLines_, unpaintedLines_;  // the lanes' boundaries
  std::vector<StrayRun> stray_;
  std::unordered_map<int64_t, int> roadCells_;  // road points near the sensor per metre square (city)
};

}  // namespace hdprior
