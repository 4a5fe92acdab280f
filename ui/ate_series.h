#pragma once
#include <string>
#include <vector>

#include "render/analysis.h"

namespace hdprior::ui {

// One line of the ATE-per-frame plot: whose error it is (its colour is its layer's), its label and
// the per-sweep errors (NaN: none).
struct AteSeries {
  enum class Kind { File, Odometry, Optimized, Comparison };
  Kind kind;
  std::string label;
  const std::vector<double>* errors;
};

// The plot's lines: an opened trajectory file's, the run's odometry (labelled built-in or with the
// file it came from, then in the file's colour) and the optimised trajectory, each when computed.
// Run B of a comparison comes last. The file's own line is left out when the run's odometry is that file (the same poses, labelled so).
std::vector<AteSeries> ateSeries(const render::Analysis& analysis);

}  // namespace hdprior::ui
