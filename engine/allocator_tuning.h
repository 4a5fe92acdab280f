#pragma once

namespace hdprior {

// Keeps freed heap memory in the process instead of returning it to the kernel after every
// sweep. Sweeps are megabyte buffers allocated and freed at 10 Hz; with glibc's defaults each
// one is a fresh mmap whose pages all fault again, which on this project's (virtualised) build
// machine made reading a sweep 15x slower (tests/bench/io_bench: 13.8 ms -> 0.9 ms).
// Call once at the start of a program (the hdprior command and the benchmarks do).
void keepFreedMemoryMapped();

}  // namespace hdprior
