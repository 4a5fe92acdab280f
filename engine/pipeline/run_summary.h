#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "engine/eval/trajectory_errors.h"

namespace hdprior {

class Session;

// The figures an A/B comparison sets side by side for one run of a log: the final trajectory's
// ATE translation (no alignment: metrics.json's "optimized", or "odometry" without priors), what
// its priors fix counted by category, and the pipeline's time.
struct RunSummary {
  ErrorStats ate;
  std::vector<std::pair<std::string, size_t>> constraints;  // countConstraints' order
  std::string constraintSummary;                            // "26 full, 51 lateral + yaw, 12 rejected"
  size_t keyframes = 0;
  double pipelineS = 0.0;
};

// Of a session run to its end (and optimised when it has priors). Throws Error when the log's
// poses do not cover the trajectory.
RunSummary summarizeRun(const Session& session);

}  // namespace hdprior
