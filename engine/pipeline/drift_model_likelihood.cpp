#include "engine/pipeline/drift_model_likelihood.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/graph/odometry_information.h"
#include "engine/odom/keyframe.h"

namespace hdprior {

namespace {

std::vector<DriftModelLikelihood::Candidate> candidatesFor(const PoseGraphOptions& configured) {
  std::vector<double> lengths{configured.mapErrorLength};
  if (configured.mapErrorLength > 0.0) lengths.push_back(0.0);
  std::vector<DriftModelLikelihood::Candidate> out;
  for (double length : lengths) {
    // Quarter decades from a hundredth to a thousand times the configured model: the data decide, both ways.
    for (int k = -8; k <= 12; ++k) out.push_back({std::pow(10.0, k / 4.0), length});
  }
  return out;
}

}  // namespace

DriftModelLikelihood::DriftModelLikelihood(const PoseGraphOptions& configured, const Eigen::Vector3d& start)
    : configured_(configured), candidates_(candidatesFor(configured)) {
  for (const Candidate& c : candidates_) filters_.emplace_back(start, c.mapErrorLength);
}

PoseGraphOptions DriftModelLikelihood::candidate(size_t i) const {
  PoseGraphOptions o = configured_;
  o.odometryTranslationSigmaPerM *= candidates_[i].factor;
  o.odometryRotationSigmaDegPerM *= candidates_[i].factor;
  o.mapErrorLength = candidates_[i].mapErrorLength;
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
    candidates_[i].logLikelihood += n.logDensity;
    filters_[i].update(n);
  }
}

void DriftModelLikelihood::restartAt(const PosePrior& prior) {
  restarted_ = true;
  for (size_t i = 0; i < filters_.size(); ++i) {
    PlanarKalman& f = filters_[i];
    candidates_[i].logLikelihood += f.innovation(prior).logDensity;
    f.widen(kForgottenPose);
    f.update(f.innovation(prior));
  }
}

std::vector<DriftModelLikelihood::Candidate> DriftModelLikelihood::scored() const {
  std::vector<Candidate> out = candidates_;
  out[pick()].chosen = true;
  return out;
}

size_t DriftModelLikelihood::pick() const {
  // After a re-anchor the odometry is known to have been metres off: no model tighter than the configured.
  auto allowed = [&](const Candidate& c) { return !restarted_ || c.factor >= 1.0; };
  double best = -std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates_)
    if (allowed(c)) best = std::max(best, c.logLikelihood);
  // Within the margin the least drift.
  size_t pick = candidates_.size();
  for (size_t i = 0; i < candidates_.size(); ++i) {
    if (!allowed(candidates_[i]) || candidates_[i].logLikelihood < best - configured_.driftModelMarginNats) continue;
    if (pick == candidates_.size() || candidates_[i].factor < candidates_[pick].factor) pick = i;
  }
  return pick;
}

PoseGraphOptions DriftModelLikelihood::likeliest() const { return candidate(pick()); }

}  // namespace hdprior
