#include "app/eval_logs.h"

#include <map>
#include <string>

#include "engine/error.h"
#include "engine/io/log_discovery.h"
#include "engine/io/log_map_files.h"

namespace hdprior::app {
namespace fs = std::filesystem;

std::vector<fs::path> evalLogs(const fs::path& dir) {
  std::vector<fs::path> logs = findArgoverseLogs(dir);
  if (logs.empty()) throw Error(dir.string(), "no Argoverse 2 logs under it");
  std::map<std::string, fs::path> seen;
  for (const fs::path& log : logs) {
    const auto [it, fresh] = seen.emplace(logIdOfFolder(log), log);
    if (!fresh) throw Error(log.string(), "has the same log id as " + it->second.string());
  }
  return logs;
}

}  // namespace hdprior::app
