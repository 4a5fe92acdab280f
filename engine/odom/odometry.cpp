#include "engine/odom/odometry.h"

#include <algorithm>
#include <string>

#include "engine/error.h"
#include "engine/odom/deskew.h"
#include "engine/odom/feature_registration.h"
#include "engine/odom/ring_features.h"

namespace hdprior {
namespace {

// The second sweep has no velocity to predict from and may start a metre or more off (a log that
// begins in motion): give it a wider basin and more re-association rounds.
RegistrationOptions startRegistration(const RegistrationOptions& ro, size_t framesSoFar) {
  if (framesSoFar != 1) return ro;
  RegistrationOptions wide = ro;
  wide.outerIterations = 3 * ro.outerIterations;
  wide.maxOuterIterations = std::max(wide.outerIterations, ro.maxOuterIterations);
  wide.maxCorrespondence = 2.0 * ro.maxCorrespondence;
  return wide;
}

constexpr double kDefaultPeriodNs = 1e8;

std::vector<Eigen::Vector3f> transformed(const std::vector<Eigen::Vector3f>& points, const SE3& T) {
  const Eigen::Isometry3f Tf = T.cast<float>();
  std::vector<Eigen::Vector3f> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) out[i] = Tf * points[i];
  return out;
}

OdometryOptions checked(OdometryOptions o) {
  checkOptionRanges("odometry options", optionFields(o.features));
  checkOptionRanges("odometry options", optionFields(o.deskew));
  checkOptionRanges("odometry options", optionFields(o.registration));
  checkOptionRanges("odometry options", optionFields(o.localMap));
  return o;
}

KeyframeOptions checked(KeyframeOptions o) {
  checkOptionRanges("keyframe options", optionFields(o));
  return o;
}

}  // namespace

Odometry::Odometry(const OdometryOptions& options, const KeyframeOptions& keyframes, PoseTrajectory given)
    : options_(checked(options)),
      keyframeOptions_(checked(keyframes)),
      localMap_(options.localMap),
      given_(std::move(given)) {
  if (const std::string problem = odometryDriftProblem(options_.drift); !problem.empty()) throw Error("odometry.drift", problem);
}

// Motion over one sweep period from the last two estimates (constant velocity); identity at start.
SE3 Odometry::predictedMotion(int64_t timestampNs, double& periodNs) const {
  periodNs = frames_.empty() ? kDefaultPeriodNs : frames_.back().periodNs;
  if (frames_.size() < 2) return SE3::Identity();
  const size_t a = frames_.size() - 2, b = frames_.size() - 1;
  periodNs = double(frames_[b].timestampNs - frames_[a].timestampNs);
  return registered_[a].inverse() * registered_[b];
}

// The pose the frame reports: the registered one, or with drift the previous reported pose times the
// degraded registered motion since the previous frame.
SE3 Odometry::reportedPose(const SE3& registered) const {
  if (frames_.empty() || !options_.drift.active()) return registered;
  return frames_.back().odomTEgo * driftedStep(registered_.back().inverse() * registered, options_.drift);
}

std::vector<Eigen::Vector3f> Odometry::deskewed(const LidarSweep& sweep, size_t frame) const {
  const OdometryFrame& f = frames_.at(frame);
  if (options_.deskew.mode == "constant_velocity") return deskewSweep(sweep.points, f.sweepMotion, f.periodNs);
  return sweepPositions(sweep.points);
}

const OdometryFrame& Odometry::registerSweep(const LidarSweep& sweep) {
  if (sweep.points.empty()) throw Error("sweep " + std::to_string(sweep.timestampNs), "has zero points");
  if (!frames_.empty() && sweep.timestampNs <= frames_.back().timestampNs) {
    throw Error("sweep " + std::to_string(sweep.timestampNs), "is not after the previous sweep");
  }
  if (!given_.empty()) {
    const SE3 pose = given_.at(sweep.timestampNs);
    return addFrame(givenFrame(sweep.timestampNs, pose), pose);
  }
  const bool deskew = options_.deskew.mode == "constant_velocity";
  const RegistrationOptions& ro = options_.registration;

  OdometryFrame frame;
  frame.timestampNs = sweep.timestampNs;
  frame.sweepMotion = predictedMotion(sweep.timestampNs, frame.periodNs);
  auto planesFor = [&](const SE3& motion) {
    const auto points = deskew ? deskewSweep(sweep.points, motion, frame.periodNs) : sweepPositions(sweep.points);
    const FeatureCloud cloud = extractFeatures(points, sweep.points, options_.features, ro.threads);
    return voxelDownsample(cloud.lessFlat, float(ro.planeDownsample));
  };
  std::vector<Eigen::Vector3f> planes = planesFor(frame.sweepMotion);
  SE3 registered = SE3::Identity();

  if (!frames_.empty()) {
    const SE3& previous = registered_.back();
    const double sinceLast = double(sweep.timestampNs - frames_.back().timestampNs);
    const SE3 guess = previous * scaleMotion(frame.sweepMotion, sinceLast / frame.periodNs);
    RegistrationResult r = registerFeatures(planes, localMap_, guess, startRegistration(ro, frames_.size()));
    if (deskew) {
      // Re-deskew with the estimated motion and refine once from the estimate.
      frame.sweepMotion = scaleMotion(previous.inverse() * r.mapTEgo, frame.periodNs / sinceLast);
      planes = planesFor(frame.sweepMotion);
      RegistrationOptions refine = ro;
      refine.outerIterations = 1;
      refine.maxOuterIterations = 1;
      r = registerFeatures(planes, localMap_, r.mapTEgo, refine);
    }
    registered = r.mapTEgo;
    frame.covariance = r.covariance;
    frame.planeResiduals = r.planeResiduals;
  }

  localMap_.add(transformed(planes, registered));
  localMap_.removeFarFrom(registered.translation().cast<float>());
  return addFrame(frame, registered);
}

// A given pose's frame: no covariance; for deskewing, the motion since the previous sweep as the
// sweep's constant velocity.
OdometryFrame Odometry::givenFrame(int64_t timestampNs, const SE3& pose) const {
  OdometryFrame frame;
  frame.timestampNs = timestampNs;
  if (!frames_.empty()) {
    frame.periodNs = double(timestampNs - frames_.back().timestampNs);
    frame.sweepMotion = registered_.back().inverse() * pose;
  }
  return frame;
}

const OdometryFrame& Odometry::addFrame(OdometryFrame frame, const SE3& registered) {
  frame.odomTEgo = reportedPose(registered);
  frames_.push_back(frame);
  registered_.push_back(registered);
  updateKeyframes();
  return frames_.back();
}

void Odometry::updateKeyframes() {
  const size_t index = frames_.size() - 1;
  const OdometryFrame& f = frames_.back();
  if (keyframes_.empty()) {
    Keyframe k;
    k.frame = index;
    k.timestampNs = f.timestampNs;
    k.odomTEgo = f.odomTEgo;
    k.submapFrames = {index};
    keyframes_.push_back(k);
    return;
  }
  const Keyframe& last = keyframes_.back();
  if (!isNewKeyframe(last.odomTEgo, f.odomTEgo, keyframeOptions_)) return;
  Keyframe k;
  k.frame = index;
  k.timestampNs = f.timestampNs;
  k.odomTEgo = f.odomTEgo;
  k.previousTThis = last.odomTEgo.inverse() * f.odomTEgo;
  k.relativeCovariance = relativeCovariance(k.previousTThis, frames_[last.frame].covariance, f.covariance);
  for (size_t i = last.frame + 1; i <= index; ++i) k.submapFrames.push_back(i);
  keyframes_.push_back(k);
}

}  // namespace hdprior
