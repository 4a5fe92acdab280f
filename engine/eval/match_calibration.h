#pragma once
#include <cstddef>
#include <span>

#include <Eigen/Core>

namespace hdprior {

// A match's error against the truth and the uncertainty it reported, per direction of the true
// vehicle frame: along the heading, lateral (left), yaw. A direction the reported information does
// not constrain has sigma = +infinity (reported unobservable).
struct MatchErrorSample {
  Eigen::Vector3d error = Eigen::Vector3d::Zero();  // metres, metres, radians
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
};

// information: over city (x, y, yaw), possibly singular. yawLength (metres) makes yaw comparable
// with translation when deciding which directions the information leaves free.
MatchErrorSample matchErrorSample(const Eigen::Vector3d& truth, const Eigen::Vector3d& estimate,
                                  const Eigen::Matrix3d& information, double yawLength = 10.0);

// How honest the reported sigmas of one direction are over many matches.
struct DirectionCalibration {
  size_t observed = 0;      // samples that report the direction observable
  double rms = 0.0;         // of their errors
  double beyond3Sigma = 0;  // share of them with |error| > 3 sigma (0.27 % for an honest Gaussian)
  double medianNees = 0;    // median of (error / sigma)^2 (0.45 for an honest Gaussian)
};

struct MatchCalibration {
  size_t matches = 0;
  DirectionCalibration along, lateral, yaw;
};

MatchCalibration calibrateMatches(std::span<const MatchErrorSample> samples);

}  // namespace hdprior
