#include "engine/odom/feature_registration.h"

#include <cmath>
#include <memory>

#include <Eigen/Eigenvalues>
#include <ceres/ceres.h>

#include "engine/odom/feature_residuals.h"
#include "engine/odom/parallel_for.h"

namespace hdprior {
namespace {

constexpr int kNeighbours = 5;

void principalAxes(const Eigen::Vector3f* pts, int count, Eigen::Vector3d& centroid, Eigen::Vector3d& values,
                   Eigen::Matrix3d& vectors) {
  centroid.setZero();
  for (int i = 0; i < count; ++i) centroid += pts[i].cast<double>();
  centroid /= count;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d d = pts[i].cast<double>() - centroid;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(cov / count);  // closed form for 3x3: several times faster than the iterative solver
  values = es.eigenvalues();  // ascending
  vectors = es.eigenvectors();
}

SE3 applyDelta(const SE3& base, const double* delta) {
  SE3 d = SE3::Identity();
  const Eigen::Vector3d w(delta[3], delta[4], delta[5]);
  if (w.norm() > 0) d.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
  d.translation() = Eigen::Vector3d(delta[0], delta[1], delta[2]);
  return base * d;
}

// One query's association: the plane n.x + d = 0 near it in the map.
struct Association {
  bool valid = false;
  Eigen::Vector3d n;
  double d = 0;
};

std::vector<Association> associate(const std::vector<Eigen::Vector3f>& queries, const VoxelFeatureMap& map,
                                   const SE3& base, const RegistrationOptions& o) {
  std::vector<Association> out(queries.size());
  const Eigen::Isometry3f baseF = base.cast<float>();
  const float gate = float(o.maxCorrespondence);
  parallelFor(queries.size(), o.threads, [&](size_t begin, size_t end) {
    Eigen::Vector3f nb[kNeighbours];
    for (size_t i = begin; i < end; ++i) {
      if (map.nearest(baseF * queries[i], kNeighbours, gate, nb) < kNeighbours) continue;
      Association& a = out[i];
      a.valid = fitPlane(nb, kNeighbours, a.n, a.d);
    }
  });
  return out;
}

// Adds the residuals of one association round; returns how many.
int addResiduals(ceres::Problem& problem, double* delta, const std::vector<Eigen::Vector3f>& planes,
                 const VoxelFeatureMap& planeMap, const SE3& base, const RegistrationOptions& o) {
  int count = 0;
  const auto surfaces = associate(planes, planeMap, base, o);
  for (size_t i = 0; i < planes.size(); ++i) {
    if (!surfaces[i].valid) continue;
    auto* cost = new ceres::AutoDiffCostFunction<PointToPlaneResidual, 1, 6>(
        new PointToPlaneResidual{planes[i].cast<double>(), surfaces[i].n, surfaces[i].d, base});
    problem.AddResidualBlock(cost, new ceres::HuberLoss(o.huberScale), delta);
    ++count;
  }
  return count;
}

Eigen::Matrix<double, 6, 6> covarianceAt(ceres::Problem& problem, int& residualCount, double& rms) {
  double cost = 0;
  std::vector<double> residuals;
  ceres::CRSMatrix J;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &residuals, nullptr, &J);
  Eigen::Matrix<double, 6, 6> JtJ = Eigen::Matrix<double, 6, 6>::Zero();
  for (int r = 0; r < J.num_rows; ++r) {
    Eigen::Matrix<double, 6, 1> row = Eigen::Matrix<double, 6, 1>::Zero();
    for (int k = J.rows[r]; k < J.rows[r + 1]; ++k) row[J.cols[k]] = J.values[k];
    JtJ += row * row.transpose();
  }
  residualCount = J.num_rows;
  rms = residualCount > 0 ? std::sqrt(2 * cost / residualCount) : 0;
  const double variance = residualCount > 6 ? 2 * cost / (residualCount - 6) : 1.0;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(JtJ);
  const double floor = std::max(1e-12, es.eigenvalues().maxCoeff() * 1e-12);
  const Eigen::Matrix<double, 6, 1> inv = es.eigenvalues().cwiseMax(floor).cwiseInverse();
  return variance * es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace

bool fitPlane(const Eigen::Vector3f* pts, int count, Eigen::Vector3d& normal, double& offset) {
  Eigen::Vector3d centroid, values;
  Eigen::Matrix3d vectors;
  principalAxes(pts, count, centroid, values, vectors);
  normal = vectors.col(0);
  offset = -normal.dot(centroid);
  for (int i = 0; i < count; ++i) {
    if (std::abs(normal.dot(pts[i].cast<double>()) + offset) > 0.2) return false;
  }
  return values[0] < 0.1 * values[1] && values[1] > 1e-3 * values[2];  // not a degenerate (collinear) patch
}

RegistrationResult registerFeatures(const std::vector<Eigen::Vector3f>& planes, const VoxelFeatureMap& planeMap,
                                    const SE3& guess, const RegistrationOptions& o) {
  RegistrationResult result;
  result.mapTEgo = guess;
  ceres::Problem::Options problemOptions;
  problemOptions.enable_fast_removal = false;
  ceres::Solver::Options solverOptions;
  solverOptions.linear_solver_type = ceres::DENSE_QR;
  solverOptions.max_num_iterations = o.solverIterations;
  solverOptions.num_threads = 1;
  solverOptions.logging_type = ceres::SILENT;
  solverOptions.minimizer_progress_to_stdout = false;
  const int minRounds = std::max(1, o.outerIterations), maxRounds = std::max(minRounds, o.maxOuterIterations);
  for (int round = 0; round < maxRounds; ++round) {
    double delta[6] = {0, 0, 0, 0, 0, 0};
    ceres::Problem problem(problemOptions);
    result.planeResiduals = addResiduals(problem, delta, planes, planeMap, result.mapTEgo, o);
    if (result.planeResiduals < 10) return result;  // too little overlap: keep the guess, covariance stays identity
    ceres::Solver::Summary summary;
    ceres::Solve(solverOptions, &problem, &summary);
    const Eigen::Map<Eigen::Matrix<double, 6, 1>> step(delta);
    const bool settled = step.head<3>().norm() < 0.01 && step.tail<3>().norm() < 0.05 * M_PI / 180.0;
    const bool last = round + 1 == maxRounds || (round + 1 >= minRounds && settled);
    if (last) {
      int count = 0;
      result.covariance = covarianceAt(problem, count, result.rmsResidual);
    }
    result.mapTEgo = applyDelta(result.mapTEgo, delta);
    if (last) break;
    if (step.head<3>().norm() < 1e-4 && step.tail<3>().norm() < 1e-5) {
      // Converged: one more round would re-associate the same pairs; take the covariance now.
      double zero[6] = {0, 0, 0, 0, 0, 0};
      ceres::Problem finalProblem(problemOptions);
      addResiduals(finalProblem, zero, planes, planeMap, result.mapTEgo, o);
      int count = 0;
      result.covariance = covarianceAt(finalProblem, count, result.rmsResidual);
      break;
    }
  }
  return result;
}

}  // namespace hdprior
