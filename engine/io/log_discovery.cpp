#include "engine/io/log_discovery.h"

#include <algorithm>
#include <set>

#include "engine/error.h"

namespace hdprior {
namespace fs = std::filesystem;

bool looksLikeArgoverseLog(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "sensors" / "lidar", ec) && fs::is_regular_file(dir / "city_SE3_egovehicle.feather", ec);
}

std::vector<fs::path> findArgoverseLogs(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(dir.string(), fs::exists(dir, ec) ? "is not a folder" : "folder not found");
  if (looksLikeArgoverseLog(dir)) return {dir};
  std::vector<fs::path> logs;
  std::set<fs::path> visited{fs::canonical(dir, ec)};  // symlinked folders are followed, each once (no cycles)
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied | fs::directory_options::follow_directory_symlink, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_directory(ec)) continue;
    std::error_code canonicalError;
    if (!visited.insert(fs::canonical(it->path(), canonicalError)).second || canonicalError ||
        it->path().filename().string().starts_with(".")) {
      it.disable_recursion_pending();
    } else if (looksLikeArgoverseLog(it->path())) {
      logs.push_back(it->path());
      it.disable_recursion_pending();
    }
  }
  if (ec) throw Error(dir.string(), "cannot list: " + ec.message());
  std::sort(logs.begin(), logs.end());
  return logs;
}

}  // namespace hdprior
