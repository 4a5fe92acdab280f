#pragma once
#include <filesystem>
#include <vector>

namespace hdprior::app {

// The logs of a batch evaluation (`eval DIR`, `merge --logs DIR`): every Argoverse 2 log under
// `dir`, sorted by path. Results are stored by log id, so the ids must be unique. Throws Error when
// `dir` holds no log or two logs share an id.
std::vector<std::filesystem::path> evalLogs(const std::filesystem::path& dir);

}  // namespace hdprior::app
