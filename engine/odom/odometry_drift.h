#pragma once
#include <string>
#include <vector>

#include "engine/geom/se3.h"

namespace hdprior {

// A reproducible degradation of an odometry's relative poses, for evaluating how the HD-map priors
// cope with the drift of real lidar odometry (0.5-1 %) rather than the simulator's (~0.01 %). Each
// sweep-to-sweep motion (t, R) becomes ((1 + scale) t, Rz(a) Ry(b) R) with a = yawDegPer100m / 100 * |t|
// and b = pitchDegPer100m / 100 * |t| (degrees; rotations about the previous ego frame's z (up) and
// y (left) axes; positive pitch tips the nose down), composed from the first pose.
struct OdometryDrift {
  double scale = 0.0;            // fraction of each step's length: 0.007 is 0.7 % too long
  double yawDegPer100m = 0.0;    // heading error per 100 m travelled, positive to the left
  double pitchDegPer100m = 0.0;

  bool active() const { return scale != 0.0 || yawDegPer100m != 0.0 || pitchDegPer100m != 0.0; }
};

// Allowed: scale in (-0.2, 0.2), yaw and pitch in [-20, 20] degrees per 100 m.
constexpr double kMaxDriftScale = 0.2;
constexpr double kMaxDriftDegPer100m = 20.0;

// The first value out of range, naming it by its config key ("scale = 0.3 is out of range (-0.2, 0.2)"),
// or an empty string.
std::string odometryDriftProblem(const OdometryDrift& drift);

// "SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M]", e.g. "0.007,0.5". Throws Error(source, reason) for
// anything else or a value out of range.
OdometryDrift parseOdometryDrift(const std::string& text, const std::string& source);

// One relative motion (a_T_b, in a's frame) degraded by the drift.
SE3 driftedStep(const SE3& step, const OdometryDrift& drift);

// A trajectory (poses in time order) with each consecutive relative motion degraded, composed from
// poses[0], which is kept. Without active drift, the poses unchanged.
std::vector<SE3> driftedPoses(const std::vector<SE3>& poses, const OdometryDrift& drift);

}  // namespace hdprior
