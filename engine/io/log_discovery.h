#pragma once
#include <filesystem>
#include <vector>

namespace hdprior {

// A folder holding sensors/lidar/ and city_SE3_egovehicle.feather: an Argoverse 2 log (it may still
// turn out to be broken when opened).
bool looksLikeArgoverseLog(const std::filesystem::path& dir);

// Every Argoverse 2 log at or below `dir`, sorted by path. Does not look inside a log, inside hidden
// folders (such as the simulator's unfinished ".<id>.partial") or through symbolic links to folders
// (a link that is itself a log is found).
// Throws Error if `dir` is not a folder or cannot be listed.
std::vector<std::filesystem::path> findArgoverseLogs(const std::filesystem::path& dir);

}  // namespace hdprior
