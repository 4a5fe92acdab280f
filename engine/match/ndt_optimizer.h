#pragma once
#include <chrono>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/match/match_options.h"

namespace hdprior {

class NdtGrid;

struct NdtOptimization {
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();
  int iterations = 0;
  // The start, then the pose after every counted iteration of every level (coarse to fine):
  // path.size() == iterations + 1.
  std::vector<Eigen::Vector3d> path;
  bool timedOut = false;
};

// Maximises the NDT score of 2-D points over the SE(2) pose, grid by grid (coarse to fine),
// each from the previous optimum: Newton steps on the score with the Hessian made negative
// definite (eigenvalues in units of x, y, yaw * yawLength lifted to a floor, so flat
// directions take gradient steps instead of huge or backward Newton steps), step lengths
// bounded per cell size, a backtracking (Armijo) line search, and the step length learnt from how
// far the score outran its quadratic model on the previous step (the four-cell score is rough, so
// pure Newton steps crawl). Coarse levels use a subset of the points and looser tolerances: they
// only seed the next level. Stops at the deadline.
NdtOptimization optimizeNdt(const std::vector<const NdtGrid*>& levels, std::span<const Eigen::Vector2d> points,
                            const Eigen::Vector3d& initial, const MatchOptions& options,
                            std::chrono::steady_clock::time_point deadline);

}  // namespace hdprior
