#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace hdprior {

// The reference ground labels of one sweep: the is_ground_0 column of an Argoverse 2 scene-flow
// label file (flow_labels.feather, one row per point of the sweep, in the sweep's row order), one
// byte per point (0 or 1). Throws Error naming the file when it cannot be read, lacks the column,
// or has another row count than the sweep's `points`.
std::vector<uint8_t> readGroundLabels(const std::filesystem::path& file, size_t points);

}  // namespace hdprior
