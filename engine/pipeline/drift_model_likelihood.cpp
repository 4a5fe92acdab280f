#include "engine/pipeline/drift_model_likelihood.h"

#include <algorithm>

#include "engine/graph/odometry_information.h"
#include "engine/odom/keyframe.h"

namespace hdprior {

DriftModelLikelihood::DriftModelLikelihood(const PoseGraphOptions& configured, const Eigen::Vector3d& start)
    : configured_(configured), factors_{1.0, 3.0, 10.0, 30.0, 100.0},
      filters_(factors_.size(), PlanarKalman(start, configured.mapErrorLength)), logLikelihood_(factors_.size(), 0.0) {}

PoseGraphOptions DriftModelLikelihood::candidate(size_t i) const {
  PoseGraphOptions o = configured_;
  o.odometryTranslationSigmaPerM *= factors_[i];
  o.odometryRotationSigmaDegPerM *= factors_[i];
  return o;
}

void DriftModelLikelihood::step(const Keyframe& keyframe) {
  for (size_t i = 0; i < filters_.size(); ++i) {
    filters_[i].predict(keyframe.previousTThis, odometryInformation(keyframe.relativeCovariance, keyframe.previousTThis, candidate(i)));
  }
}

void DriftModelLikelihood::observe(const PosePrior& prior) {
  for (size_t i = 0; i < filters_.size(); ++i) {
    const PlanarKalman::Innovation n = filters_[i].innovation(prior);
    logLikelihood_[i] += n.logDensity;
    filters_[i].update(n);
  }
}

PoseGraphOptions DriftModelLikelihood::likeliest() const {
  const auto best = std::max_element(logLikelihood_.begin(), logLikelihood_.end());
  return candidate(size_t(best - logLikelihood_.begin()));
}

}  // namespace hdprior
