#include "engine/sim/demo_log.h"

#include <cstdlib>
#include <string>
#include <system_error>
#include <unistd.h>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/sim/log_writer.h"

namespace hdprior {
namespace fs = std::filesystem;

fs::path demoCacheDir() {
  if (const char* d = std::getenv("HDPRIOR_CACHE_DIR"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return fs::path(d) / "hdprior";
  if (const char* d = std::getenv("HOME"); d && *d) return fs::path(d) / ".cache" / "hdprior";
  return fs::temp_directory_path() / "hdprior-cache";
}

fs::path demoLogPath(const std::function<void(size_t, size_t)>& progress) {
  const fs::path root = demoCacheDir() / ("demo-v" + std::to_string(kDemoLogVersion));
  const fs::path done = root / "complete";
  std::error_code ec;
  if (fs::exists(done, ec)) {
    const std::string id = readFileText(done);
    if (!id.empty() && fs::is_directory(root / id, ec)) return root / id;
  }
  // Generate into a private folder, then publish it with one rename.
  const fs::path work = demoCacheDir() / ("demo-v" + std::to_string(kDemoLogVersion) + ".tmp" + std::to_string(getpid()));
  fs::remove_all(work, ec);
  SimulationOptions o;
  o.townSeed = 1;
  o.town.gridCols = 3;
  o.town.gridRows = 3;
  o.town.blockSize = 180.0;
  o.town.corridors = 1;
  o.town.corridorLength = 300.0;
  o.seconds = 10.0;
  o.seed = 1;
  o.outDir = work;
  o.progress = progress;
  const SimulationResult r = simulateLog(o);
  writeFileAtomically(work / "complete", r.logId);
  fs::rename(work, root, ec);
  if (ec) fs::remove_all(work, ec);  // another process published it first
  if (!fs::exists(root / r.logId / "city_SE3_egovehicle.feather", ec))
    throw Error(root.string(), "demo log cache is unusable; delete it and retry");
  return root / r.logId;
}

}  // namespace hdprior
