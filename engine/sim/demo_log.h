#pragma once
#include <filesystem>
#include <functional>

namespace hdprior {

// Bumped whenever the simulator's output changes, so stale cached demos are not reused.
inline constexpr int kDemoLogVersion = 3;  // 2: routes smoothed through junctions; 3: road paint

// The folder the demo log is cached in: $HDPRIOR_CACHE_DIR, else $XDG_CACHE_HOME/hdprior,
// else $HOME/.cache/hdprior, else <temp>/hdprior-cache.
std::filesystem::path demoCacheDir();

// The path of a small demo log (a procedural town, 10 s along a route), generated into
// demoCacheDir()/demo-v<version>/ on first use and reused afterwards. Safe against
// concurrent callers (each generates into its own temporary folder; the first rename wins).
std::filesystem::path demoLogPath(const std::function<void(size_t, size_t)>& progress = {});

}  // namespace hdprior
