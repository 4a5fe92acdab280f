// The main of every benchmark program: the same allocator settings as the hdprior command,
// so the figures measure what the tool does.
#include <benchmark/benchmark.h>

#include "engine/allocator_tuning.h"

int main(int argc, char** argv) {
  hdprior::keepFreedMemoryMapped();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
