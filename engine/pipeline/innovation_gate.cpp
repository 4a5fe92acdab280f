#include "engine/pipeline/innovation_gate.h"

#include <cmath>
#include <numbers>

namespace hdprior {

InnovationGate::InnovationGate(const Eigen::Vector3d& start, double mapErrorLength, double probability, int reanchorPriors)
    : gate_(start, mapErrorLength), probability_(probability), reanchorPriors_(reanchorPriors) {}

void InnovationGate::predict(const Eigen::Vector3d& latestPose, const SE3& previousTThis, const Matrix6d& stepInformation) {
  gate_.setMean(latestPose);
  gate_.predict(previousTThis, stepInformation);
  if (challenger_) challenger_->predict(previousTThis, stepInformation);
}

InnovationGate::Verdict InnovationGate::judge(size_t keyframe, const PosePrior& prior, bool outsidePrediction) {
  Verdict v;
  const PlanarKalman::Innovation t = gate_.innovation(prior);
  v.chi2 = t.chi2;
  if (probability_ > 0.0 && t.dof > 0) v.quantile = chiSquareQuantile(probability_, t.dof);
  if (outsidePrediction || (v.quantile > 0.0 && t.chi2 > v.quantile)) {
    v.admitted = followGatedRun(keyframe, prior, v);
    return v;
  }
  gate_.update(t);
  challenger_.reset();
  run_.clear();
  v.admitted = true;
  return v;
}

bool InnovationGate::followGatedRun(size_t keyframe, const PosePrior& prior, Verdict& v) {
  if (reanchorPriors_ <= 0) return false;
  bool agrees = false;
  if (challenger_) {
    const PlanarKalman::Innovation c = challenger_->innovation(prior);
    agrees = c.dof > 0 && c.chi2 <= chiSquareQuantile(probability_, c.dof);
    if (agrees) challenger_->update(c);
  }
  if (!agrees) {
    // A new run: the challenger keeps the gate's map offset, not its pose.
    challenger_ = gate_;
    challenger_->widen(kForgottenPose);
    challenger_->update(challenger_->innovation(prior));
    run_.clear();
  }
  run_.push_back(keyframe);
  if (int(run_.size()) < reanchorPriors_) return false;
  Eigen::Vector3d d = challenger_->mean() - gate_.mean();
  d.z() = std::remainder(d.z(), 2.0 * std::numbers::pi);
  gate_.widen(d * d.transpose());
  gate_.update(gate_.innovation(prior));
  v.reanchored.assign(run_.begin(), run_.end() - 1);
  challenger_.reset();
  run_.clear();
  return true;
}

}  // namespace hdprior
