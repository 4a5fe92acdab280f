#include "engine/graph/pose_graph.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <ceres/ceres.h>

#include "engine/error.h"
#include "engine/graph/pose_factors.h"

namespace hdprior {

struct PoseGraph::Impl {
  ceres::Problem problem;
  std::vector<std::unique_ptr<Eigen::Quaterniond>> q;  // stable addresses for Ceres
  std::vector<std::unique_ptr<Eigen::Vector3d>> t;
  std::vector<double> routeMetres;  // along the odometry, from the first keyframe
  std::vector<std::unique_ptr<Eigen::Vector2d>> mapOffset;  // the map's error at each prior (mapErrorLength > 0)
  std::vector<double> mapOffsetMetres;
  Eigen::Vector2d zeroOffset = Eigen::Vector2d::Zero();  // held constant: priors without a map offset state
};

PoseGraph::PoseGraph(PoseGraphOptions options) : impl_(std::make_unique<Impl>()), options_(options) {
  checkOptionRanges("pose graph options", optionFields(options_));
  impl_->problem.AddParameterBlock(impl_->zeroOffset.data(), 2);
  impl_->problem.SetParameterBlockConstant(impl_->zeroOffset.data());
}

double* PoseGraph::addMapOffsetState(size_t i, double sigma) {
  Impl& m = *impl_;
  const bool first = m.mapOffset.empty();
  const double metres = first ? 0.0 : m.routeMetres[i] - m.mapOffsetMetres.back();
  const MapOffsetStep step(metres, options_.mapErrorLength, sigma, first);
  double* previous = first ? m.zeroOffset.data() : m.mapOffset.back()->data();
  m.mapOffset.push_back(std::make_unique<Eigen::Vector2d>(step.a * Eigen::Map<Eigen::Vector2d>(previous)));
  m.mapOffsetMetres.push_back(m.routeMetres[i]);
  double* offset = m.mapOffset.back()->data();
  m.problem.AddParameterBlock(offset, 2);
  m.problem.AddResidualBlock(new ceres::AutoDiffCostFunction<MapOffsetStep, 2, 2, 2>(new MapOffsetStep(step)), nullptr,
                             previous, offset);
  return offset;
}

PoseGraph::~PoseGraph() = default;

size_t PoseGraph::addKeyframe(int64_t timestampNs, const SE3& initial) { return addKeyframe(timestampNs, initial, initial); }

size_t PoseGraph::addKeyframe(int64_t timestampNs, const SE3& initial, const SE3& start) {
  if (!timestamps_.empty() && timestampNs <= timestamps_.back()) {
    throw Error("pose graph", "keyframe timestamps must increase");
  }
  timestamps_.push_back(timestampNs);
  initial_.push_back(initial);
  impl_->q.push_back(std::make_unique<Eigen::Quaterniond>(Eigen::Quaterniond(start.rotation()).normalized()));
  impl_->t.push_back(std::make_unique<Eigen::Vector3d>(start.translation()));
  impl_->routeMetres.push_back(impl_->routeMetres.empty() ? 0.0 : impl_->routeMetres.back());
  impl_->problem.AddParameterBlock(impl_->q.back()->coeffs().data(), 4, new ceres::EigenQuaternionManifold);
  impl_->problem.AddParameterBlock(impl_->t.back()->data(), 3);
  if (timestamps_.size() == 1) {  // the gauge: the first keyframe is the given start
    impl_->problem.SetParameterBlockConstant(impl_->q.back()->coeffs().data());
    impl_->problem.SetParameterBlockConstant(impl_->t.back()->data());
  }
  return timestamps_.size() - 1;
}

void PoseGraph::addOdometry(size_t i, size_t j, const SE3& iTj, const Matrix6d& information) {
  if (i >= size() || j >= size() || i == j) throw Error("pose graph", "odometry between unknown keyframes");
  if (j == i + 1) impl_->routeMetres[j] = impl_->routeMetres[i] + iTj.translation().norm();
  auto* cost = new ceres::AutoDiffCostFunction<BetweenFactor, 6, 4, 3, 4, 3>(
      new BetweenFactor(iTj, sqrtInformation<6>(information)));
  impl_->problem.AddResidualBlock(cost, nullptr, impl_->q[i]->coeffs().data(), impl_->t[i]->data(),
                                  impl_->q[j]->coeffs().data(), impl_->t[j]->data());
}

void PoseGraph::addPrior(size_t i, const PosePrior& prior) {
  if (i >= size()) throw Error("pose graph", "prior on an unknown keyframe");
  const bool correlated = options_.mapErrorLength > 0.0 && prior.mapSigma > 0.0;
  const PosePrior p = correlated ? prior : withIndependentMapError(prior);
  double* offset = correlated ? addMapOffsetState(i, prior.mapSigma) : impl_->zeroOffset.data();
  auto* cost = new ceres::AutoDiffCostFunction<PriorFactor, 4, 4, 3, 2>(new PriorFactor(p.pose, sqrtInformation<4>(p.information)));
  impl_->problem.AddResidualBlock(cost, new ceres::HuberLoss(options_.priorHuber), impl_->q[i]->coeffs().data(),
                                  impl_->t[i]->data(), offset);
}

SolveSummary PoseGraph::solve() {
  SolveSummary summary;
  if (size() == 0) return summary;
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.max_num_iterations = options_.maxIterations;
  o.num_threads = 1;  // deterministic
  ceres::Solver::Summary s;
  ceres::Solve(o, &impl_->problem, &s);
  summary.iterations = int(s.iterations.size());
  summary.initialCost = s.initial_cost;
  summary.finalCost = s.final_cost;
  summary.converged = s.termination_type == ceres::CONVERGENCE;
  return summary;
}

SE3 PoseGraph::pose(size_t i) const {
  if (i >= size()) throw Error("pose graph", "no keyframe " + std::to_string(i));
  return makeSE3(*impl_->q[i], *impl_->t[i]);
}

std::vector<SE3> PoseGraph::poses() const {
  std::vector<SE3> out;
  for (size_t i = 0; i < size(); ++i) out.push_back(pose(i));
  return out;
}

PoseTrajectory PoseGraph::correct(const PoseTrajectory& trajectory) const {
  if (size() == 0) return trajectory;
  std::vector<SE3> corrections;
  for (size_t i = 0; i < size(); ++i) corrections.push_back(pose(i) * initial_[i].inverse());
  std::vector<SE3> out;
  for (size_t k = 0; k < trajectory.size(); ++k) {
    const int64_t t = trajectory.timestamps()[k];
    const auto it = std::upper_bound(timestamps_.begin(), timestamps_.end(), t);
    SE3 c;
    if (it == timestamps_.begin()) {
      c = corrections.front();
    } else if (it == timestamps_.end()) {
      c = corrections.back();
    } else {
      const size_t j = size_t(it - timestamps_.begin()), i = j - 1;
      const double s = double(t - timestamps_[i]) / double(timestamps_[j] - timestamps_[i]);
      c = interpolate(corrections[i], corrections[j], s);
    }
    out.push_back(c * trajectory.poses()[k]);
  }
  return PoseTrajectory(trajectory.timestamps(), std::move(out), "corrected trajectory");
}

}  // namespace hdprior
