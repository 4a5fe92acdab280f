#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/option_fields.h"

namespace hdprior {

// Road-point extraction: of the ground points, the road surface the vehicle drives on,
// separated from sidewalks and verges at the curbs. Each laser ring is walked along its
// azimuth, over ground points only, from seeds ahead of and behind the vehicle in its lane at
// road level (only as far as the lane goes), outwards in both directions; the walk stops
// where the height differs by more than a step from any road point of the walk just before it (a
// curb: about 0.15 m) or the gap along the ring grows too long. Non-ground returns (cars, pedestrians) are stepped over, so the
// walk continues on the road behind an occluder but not onto a raised sidewalk.
struct RoadPointOptions {
  double groundZ = -0.32;          // road level under the ego origin
  double maxRange = 40.0;          // metres from the origin
  double maxStep = 0.05;           // height change allowed between consecutive ground points ...
  double stepPerMetre = 0.01;      // ... plus this much per metre between them, ...
  double maxCamber = 0.04;         // ... after the road's cross slope over the window (up to this) is taken out;
                                   // design standards: 1.5-2.5 %, up to 4 % (0: heights compared level)
  double maxGap = 5.0;             // a longer gap along the ring ends the walk, metres
  double window = 3.0;             // the step test covers the walk's road points this far back
  int maxSkipped = 3;              // this many consecutive points off the road height end the walk
  // A road without a kerb, or with one lower than maxStep, still ends at its gutter: the lowest line
  // of its cross-section, where the camber comes down and the verge goes up (gutters 2-5 cm deep). A
  // point gutterRise above the walk's lowest point within gutterWindow behind it, where the walk came
  // down into that low by gutterRise too, is past the gutter (0: off).
  double gutterRise = 0.03;        // metres
  double gutterWindow = 1.0;       // metres
  // Seeds: ground points within this of the vehicle's x axis (its own width, about 1.9 m: wider seeds
  // of a vehicle close to a low kerb lie on the sidewalk, and whole rings are walked from there) ...
  double seedHalfWidth = 1.0;
  double seedTolerance = 0.12;     // ... within this of groundZ ...
  double seedTolerancePerMetre = 0.01;  // ... plus this much per metre of range
  // Seeds only as far along the lane as its height profile goes on without a kerb up (not beyond a
  // T-junction's far kerb, from where whole rings would be walked on the sidewalk):
  double laneStep = 0.08;          // a rise this far above the lane's height profile ends the lane (kerbs: 0.10-0.20 m)
  double gradeLength = 10.0;       // metres of lane behind a point that give the road's grade there
  double laneObjectHeight = 0.35;  // a lane point higher than this above the profile is an object, not a kerb
  double laneEndLength = 1.0;      // the lane ends where its points stay above the profile this far along it
};
std::vector<OptionField> optionFields(RoadPointOptions& o);  // its configuration keys


inline constexpr uint8_t kRoadPoint = 1;
inline constexpr uint8_t kCurbPoint = 2;  // a road point where the walk ended at a height step it saw, no object on it (a curb)

// One flag per point: 0 = not road, kRoadPoint, or kCurbPoint (also road). `ring` is each point's
// laser number, `ground` its ground flag (segmentGround); all three have the points' length.
std::vector<uint8_t> extractRoadPoints(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> ring,
                                       std::span<const uint8_t> ground, const RoadPointOptions& options = {});

// The flagged points projected to the plane (x, y), thinned to one point (the mean) per
// `cell` metres square (0 keeps every point), in a deterministic order.
std::vector<Eigen::Vector2d> planarPoints(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> flags,
                                          double cell = 0.0);

}  // namespace hdprior
