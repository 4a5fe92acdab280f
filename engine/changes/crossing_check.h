#pragma once
#include <cmath>
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

// The road's mean brightness (SweepPaint::brightness, averaged per cell of options.paintCell over
// the drive) inside a crossing's outline and in the band 1-3 m around it (road cells off the map's
// paint): paint lifts the inside. The road itself varies from place to place more than its cells'
// count says (sealed cracks, repairs, the angle the rings meet it at), so the lift is weighed
// against the spread of the lifts the same outline shows on bare road nearby (`spread`).
struct CrossingBrightness {
  int insideCells = 0, aroundCells = 0;
  double inside = 0.0, around = 0.0;  // the mean of the cells' means
  double standardError = 0.0;         // of inside - around, cells as the samples
  double spread = 0.0;                // the log's: the RMS lift of its controls beyond their standard errors
  double lift() const { return inside - around; }
  double uncertainty() const { return std::sqrt(standardError * standardError + spread * spread); }
  double z() const { return uncertainty() > 0.0 ? lift() / uncertainty() : 0.0; }
};

// A pedestrian crossing of the map, judged by how much brighter the road inside it is than around it.
struct CrossingVerdict {
  int64_t id = 0;
  std::vector<Eigen::Vector2d> outline;  // edge1, then edge2 backwards (city x, y)
  MapVerdict verdict = MapVerdict::Unobserved;
  double confidence = 0.0;
  int roadCells = 0, paintCells = 0;  // cells (options.paintCell) seen near the sensor inside the outline; those with paint
  double asphaltShare = 0.0;          // the share of the log's road cells with paint, off the map's paint
  CrossingBrightness brightness;
  double paintedLift = 0.0;  // the median lift of the log's consistent crossings (0: none)
  int controls = 0;          // the log's controls the spread was measured on
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
// The road near the sensor is cut into cells of options.paintCell. A crossing is judged by its
// CrossingBrightness: consistent when its lift stands out by options.crossingZ times its
// uncertainty, contradicted when it does not (options.crossingAbsentZ at most) while lying that
// many times below the lift of the log's consistent crossings. It is unobserved with fewer than 30
// cells inside or around, in a log none of whose crossings stands out (its paint may be too faint),
// and in one with fewer than 5 controls: the crossings' outlines moved 8, 16 and 24 m along the
// road either way, where bare road fills them.
// A cell with a paint run in it over the drive is painted. Paint on a painted lane line
// (options.paintLineReach) is the line's. Off the map's paint, a band options.crossingDepth deep
// along the lanes that is painted like a crossing at both its edges, between flanks that are not,
// is a missing crossing (options.missingCrossingEvidence), judged against the log's asphalt: the
// share of painted cells off the map's lane lines and crossings (a road's own marks: repairs,
// sealed cracks, bright aggregate).
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
  // Inside: the cells of place `inside` within the outline; around: road cells 1-3 m out.
  CrossingBrightness brightnessOf(const std::vector<Eigen::Vector2d>& outline, uint8_t inside) const;
  // The RMS lift of the crossings' controls beyond their standard errors, and how many there are.
  std::pair<double, int> roadSpread() const;

  ChangeOptions options_;
  LaneLineIndex lines_;
  std::vector<Crossing> crossings_;
  std::vector<StrayRun> stray_;
  PaintCells cells_;
};

}  // namespace hdprior
