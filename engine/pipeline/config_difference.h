#pragma once
#include <string>
#include <vector>

#include "engine/pipeline/config.h"

namespace hdprior {

// The keys whose values differ between two configurations, in the configuration file's order:
// "match.outlier_ratio 0.55 -> 0.6". Empty when they are the same.
std::vector<std::string> configDifferences(const Config& before, const Config& after);

}  // namespace hdprior
