#pragma once
#include <string>

#include "engine/odom/odometry_drift.h"
#include "engine/option_fields.h"

namespace hdprior {

// LOAM feature extraction per ring (see ring_features.h). Curvature is the LOAM paper's
// c = |sum_j (p_j - p_i)| / (2k |p_i|) over the k neighbours on each side along the ring.
struct FeatureOptions {
  int neighbours = 5;               // k
  int sectors = 6;                  // per ring, each picks its own features
  int flatPerSector = 4;            // planes ("flat")
  // c at or above this marks a corner or an edge (a 90 deg corner at 0.2 deg steps: ~0.01): such a
  // point is never a plane point ("less flat"). Edges themselves are not registered.
  double edgeCurvature = 0.005;
  double planeCurvature = 0.0025;   // c below this may be a plane
  double minRange = 2.0;            // metres; nearer returns hit the vehicle
  double maxRange = 120.0;
  double occlusionRatio = 0.1;      // neighbour range jump (relative) that marks the far side occluded
  double parallelBeamRatio = 0.02;  // neighbour spacing / range above this on both sides: beam grazes surface
  double maxGapDeg = 1.0;           // azimuth gap that breaks a ring into segments
};

// What the stored sweep points mean, and how to deskew them.
// "none": points are already motion-compensated to the sweep timestamp (Argoverse 2; see
// docs/formats.md, What the stored points mean). "constant_velocity": points are in the ego frame at their own time
// (sweep timestamp + offset_ns); they are moved to the sweep timestamp with the predicted motion and
// re-deskewed with the estimated motion.
struct DeskewOptions {
  std::string mode = "none";
};

struct RegistrationOptions {
  int outerIterations = 2;          // re-association rounds
  // Rounds go on past outerIterations while a round still moves the pose 1 cm or 0.05 deg (a
  // constant-velocity guess in a sharp turn is degrees off, and each round gets part of the way).
  int maxOuterIterations = 6;
  int solverIterations = 6;         // Ceres iterations per round
  double huberScale = 0.1;          // metres, robust loss
  double maxCorrespondence = 1.0;   // metres, nearest-neighbour gate
  double planeDownsample = 0.8;     // voxel size for the scan's plane queries
  int threads = 2;                  // correspondence search and feature extraction
};

// The local map: plane points in a voxel hash, bounded by a radius around the vehicle and a point cap per voxel.
struct LocalMapOptions {
  double voxelSize = 1.0;
  int maxPointsPerVoxel = 10;
  double minPointSpacing = 0.3;     // a new point closer than this to one in its voxel is dropped
  double radius = 80.0;             // voxels farther than this from the vehicle are removed
};

struct KeyframeOptions {
  double distance = 2.0;            // metres travelled since the previous keyframe
  double rotationDeg = 10.0;        // or degrees turned
};

struct OdometryOptions {
  FeatureOptions features;
  DeskewOptions deskew;
  RegistrationOptions registration;
  LocalMapOptions localMap;
  // Degrades the reported trajectory (frames, keyframes) only; registration and the local map stay
  // on the odometry's own estimate. Off (all zero) by default: for evaluation.
  OdometryDrift drift;
};

// The configuration keys of each (engine/odom/odometry_option_fields.cpp).
std::vector<OptionField> optionFields(FeatureOptions& o);
std::vector<OptionField> optionFields(DeskewOptions& o);
std::vector<OptionField> optionFields(RegistrationOptions& o);
std::vector<OptionField> optionFields(LocalMapOptions& o);
std::vector<OptionField> optionFields(KeyframeOptions& o);


}  // namespace hdprior
