#pragma once
#include <algorithm>
#include <thread>
#include <vector>

namespace hdprior {

// Runs fn(begin, end) over [0, n) split into `threads` fixed contiguous chunks (fewer when n is below `grain` per thread). Results written by
// index are the same for any thread count, so callers stay deterministic.
template <typename Fn>
void parallelFor(size_t n, int threads, Fn fn, size_t grain = 64) {
  const size_t t = std::max<size_t>(1, std::min<size_t>(size_t(std::max(threads, 1)), n / grain + 1));
  if (t == 1) {
    fn(size_t(0), n);
    return;
  }
  std::vector<std::thread> workers;
  for (size_t i = 1; i < t; ++i) workers.emplace_back(fn, n * i / t, n * (i + 1) / t);
  fn(size_t(0), n / t);
  for (auto& w : workers) w.join();
}

}  // namespace hdprior
