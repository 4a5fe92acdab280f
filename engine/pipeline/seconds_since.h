#pragma once
#include <chrono>

namespace hdprior {

// Wall-clock seconds from `start` to now, for the stage times a run reports.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hdprior
