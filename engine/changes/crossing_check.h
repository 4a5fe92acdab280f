#pragma once
#include <cstdint>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/changes/lane_line_index.h"
#include "engine/changes/map_verdict.h"
#include "engine/changes/paint_cells.h"
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
  int roadCells = 0, paintCells = 0;  // cells (options.paintCell) seen near the sensor inside the outline; those with paint
  double asphaltShare = 0.0;          // the share of the log's road cells with paint, off the map's paint
  int firstFrame = -1, bestFrame = -1;  // the first frame with road points inside; the one with most paint (or road points)
};

// A 0.25 m cell of road that held a paint run over the drive.
struct PaintedCell {
  Eigen::Vector2d centre;
  bool onMapPaint = false;  // within reach of a painted lane line or in a crossing; else the road's own mark or unmapped paint
};

// Paint across the road where the map has no crossing and no painted lane line.
struct MissingCrossing {
  std::vector<Eigen::Vector2d> outline;  // a rectangle around the paint, counter-clockwise
  double confidence = 0.0;
  int roadCells = 0, paintCells = 0;
  int firstFrame = -1, bestFrame = -1;
};

// The paint evidence of a log's sweeps against its map's crossings.
//
// The road near the sensor is cut into cells of options.paintCell; a cell with a paint run in it
// over the drive is painted. A road's own marks (repairs, sealed cracks, bright aggregate) are
// painted cells too, fixed in the world, so a crossing is judged against the log's asphalt: the
// share of painted cells off the map's lane lines and crossings. A crossing whose painted share is
// options.crossingContrast times that is consistent, one whose share is the asphalt's (at most
// options.crossingAsphaltLevel times it) is contradicted, by their likelihood ratio (binomial per
// cell); too few cells to tell leave it
// unobserved, and so does a log in which no crossing shows paint (faint paint reads as asphalt).
// Paint on a painted lane line (options.paintLineReach) is the line's. Off the map's paint, a band
// options.crossingDepth deep along the lanes that is painted like a crossing at both its edges,
// between flanks that are not, is a missing crossing (options.missingCrossingEvidence).
class CrossingEvidence {
 public:
  CrossingEvidence(const VectorMap& map, const ChangeOptions& options);

  // A sweep's paint (findSweepPaint) at city_T_ego.
  void add(int frame, const SweepPaint& paint, const SE3& cityTEgo);

  std::vector<CrossingVerdict> verdicts() const;
  std::vector<MissingCrossing> missing() const;
  // The share of the log's road cells off the map's paint that are painted (0 when none is seen).
  double asphaltShare() const;
  std::vector<PaintedCell> paintedCells() const;

 private:
  enum class Place : uint8_t { Road, PaintedLine, Crossing };  // a PaintCell's place
  struct Crossing {
    CrossingVerdict verdict;
    std::vector<Eigen::Vector2d> reach;     // the outline grown by half a metre: paint at the mapped edge counts
    std::vector<Eigen::Vector2d> explains;  // grown by a metre: paint here is the crossing's, never a missing one
    Eigen::Vector2d lo, hi;                 // the bounds of `explains`
    int bestFrameRuns = -1, bestFrameRoadPoints = -1;
  };
  struct StrayRun {
    Eigen::Vector2d city;
    int frame;
  };
  PaintCell& cellAt(const Eigen::Vector2d& city);
  PaintTally tallyIn(const std::vector<Eigen::Vector2d>& outline, Place place) const;
  // Road cells (Place::Road) in a rectangle: u along `along` from u0 to u1, v across from v0 to v1, about `centre`.
  PaintTally tallyInBand(const Eigen::Vector2d& centre, const Eigen::Vector2d& along, double u0, double u1, double v0, double v1) const;
  double evidence(const PaintTally& t, double asphaltShare) const;

  ChangeOptions options_;
  LaneLineIndex lines_;
  std::vector<Crossing> crossings_;
  std::vector<StrayRun> stray_;
  PaintCells cells_;
};

}  // namespace hdprior
