#pragma once
// The probes' command line: LOG STEP (every STEP-th sweep of the log).
#include <cstdio>
#include <cstdlib>

namespace hdprior {

// STEP, or 0 after printing the usage line when the arguments are bad.
inline size_t probeStep(int argc, char** argv, const char* name) {
  if (argc < 3 || std::atol(argv[2]) <= 0) {
    std::fprintf(stderr, "usage: %s LOG STEP\n", name);
    return 0;
  }
  return size_t(std::atol(argv[2]));
}

}  // namespace hdprior
