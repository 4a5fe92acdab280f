#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "engine/changes/boundary_stretch.h"
#include "engine/changes/change_options.h"
#include "engine/changes/crossing_check.h"
#include "engine/changes/lane_line_check.h"
#include "engine/changes/map_verdict.h"
#include "engine/changes/missing_surface.h"
#include "engine/changes/sweep_alignment.h"
#include "engine/geom/pose_trajectory.h"
#include "engine/lidar/sweep_road_points.h"

namespace hdprior {

class ArgoverseLog;
class HdMap;

// A drivable area's verdict: contradicted when a stretch of it is, else consistent when one is
// observed, else unobserved; the confidence and frames of the stretch that decided it.
struct DrivableAreaVerdict {
  int64_t id = 0;
  MapVerdict verdict = MapVerdict::Unobserved;
  double confidence = 0.0;
  int firstFrame = -1, bestFrame = -1;
};

// What the lidar of a log says of its HD map's drivable area, along the run's poses.
struct MapChangeReport {
  std::vector<BoundaryStretch> stretches;         // of the polygons whose boundary the evidence covers
  std::vector<DrivableAreaVerdict> drivableAreas;  // every polygon of the map, in its order
  std::vector<MissingSurface> missing;
  std::vector<CrossingVerdict> crossings;  // every pedestrian crossing of the map, in its order (detectMapChanges)
  std::vector<MissingCrossing> missingCrossings;
  std::vector<LaneLineStretch> laneLines;  // the stretches of painted lane lines with road seen beside them
  std::vector<PaintedCell> paint;          // what the crossing and lane-line checks read
  double paintCell = 0.25;                 // metres, the width of those cells
  double observedBoundaryKm = 0.0;  // of the map's boundary with a verdict
  SurfaceEvidence evidence;         // what it was judged on
  size_t frames = 0;                // sweeps added to the evidence
  std::vector<MisalignedSweep> misaligned;  // sweeps left out: their kerbs line up with the map only shifted
  double drivenKm = 0.0;            // along the poses of those sweeps
};

// Adds a sweep every options.frameSpacing metres of the poses (city_T_ego, e.g. a run's
// optimised trajectory; sweeps they do not cover are left out) to the surface evidence,
// labelled as the road points are (two sweeps at a time, added in order), and its paint to the
// crossing and lane-line evidence, unless its kerbs say its pose is off (SweepAlignment); then judges every boundary stretch, crossing and lane-line
// stretch and finds the missing surfaces and crossings. progress(done, total) after each sweep; cancel stops between sweeps (the report
// then covers what was added). Throws Error for an unreadable sweep file, naming it.
MapChangeReport detectMapChanges(const ArgoverseLog& log, const HdMap& map, const PoseTrajectory& poses,
                                 const SweepRoadPointOptions& roadPoints, const ChangeOptions& options,
                                 const std::function<void(size_t, size_t)>& progress = {},
                                 const std::atomic<bool>* cancel = nullptr);

// The verdicts on evidence already gathered (frames and drivenKm are left at 0).
MapChangeReport judgeMapChanges(SurfaceEvidence evidence, const HdMap& map, const ChangeOptions& options);

// The log's map as the check along `poses` needs it: the drivable area and its distance field
// within reach of the sweeps it reads (the road points' range, a boundary reading's reach and 10 m
// of distance beyond), the ground-height raster (no NDT grids). Throws Error naming the file that
// is wrong.
std::unique_ptr<HdMap> loadCheckedMap(const ArgoverseLog& log, const PoseTrajectory& poses, const SweepRoadPointOptions& roadPoints,
                                      const ChangeOptions& options);

// The element verdicts from the stretches (every polygon of the map, in its order).
std::vector<DrivableAreaVerdict> drivableAreaVerdicts(const VectorMap& map, const std::vector<BoundaryStretch>& stretches);

}  // namespace hdprior
