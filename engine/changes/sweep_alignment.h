#pragma once
#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/geom/se3.h"
#include "engine/io/vector_map.h"
#include "engine/lidar/sweep_road_points.h"

namespace hdprior {

class BoundaryDistance;
class GroundHeight;

// Whether a sweep fits the map at its pose. A map change moves one polygon's boundary; a pose that
// is off moves every kerb in view, so a shift of the whole sweep lines them up again. And the road
// under the car is the map's road whatever changed at the boundaries: where it stands off the
// ground-height raster, the pose is off (in height, or sideways on a slope). Such a sweep says
// nothing about the map that its pose can be trusted for: the check leaves it out. One polygon alone
// in view cannot tell (it may be the one that moved).
struct SweepAlignment {
  int kerbs = 0;           // kerb points of the sweep within the road points' range
  int alignedAtPose = 0;   // of them within ChangeOptions::cell of a mapped boundary
  int alignedShifted = 0;  // ... the most under a shift of the sweep within ChangeOptions::reach
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // that shift, levelled ego frame, metres
  int polygonsShifted = 0;  // drivable areas whose boundary holds 2 or more of the kerbs the shift lines up
  // The road points within ChangeOptions::groundRange of the sensor over the raster: their median
  // height above it (metres; 0 without a raster) and how many there are.
  double roadOverRaster = 0.0;
  int roadOnRaster = 0;

  // Twice the kerbs line up under a shift beyond the tolerance (at least 2 x minSamples of them),
  // on two polygons or more, and the poses can be that far off after `driven` metres
  // (ChangeOptions::poseErrorPerMetre); or the sweep is offGround.
  bool misaligned(const ChangeOptions& options, double driven) const;
  // The road under the car stands off the raster by more than ChangeOptions::groundOffsetLimit.
  bool offGround(const ChangeOptions& options) const;
};

// A sweep the check left out, and why.
struct MisalignedSweep {
  int frame = -1;
  SweepAlignment alignment;
  bool followsAnother = false;  // the sweep read before it was left out too
  bool offGround = false;       // left out for its road's height over the raster (SweepAlignment::offGround)
};

// `sweep` is labelSweep's (levelled with the pose's roll and pitch); the shifts are tried on a grid
// of ChangeOptions::cell. `ground` may be null (a map without a raster).
SweepAlignment sweepAlignment(const LabelledSweep& sweep, const SE3& cityTEgo, const BoundaryDistance& distance,
                              const std::vector<DrivableArea>& areas, const GroundHeight* ground, const ChangeOptions& options);

}  // namespace hdprior
