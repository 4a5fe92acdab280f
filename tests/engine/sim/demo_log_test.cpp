// The demo log: generated once into the cache folder, then reused.
#include "engine/sim/demo_log.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iterator>

#include "engine/io/argoverse_log.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

TEST(DemoLog, IsGeneratedOnceIntoTheCacheAndReused) {
  const fs::path cache = test::freshOutputDir("demo_cache");
  ::setenv("HDPRIOR_CACHE_DIR", cache.c_str(), 1);
  const fs::path first = demoLogPath();
  EXPECT_EQ(first.parent_path(), cache / ("demo-v" + std::to_string(kDemoLogVersion)));
  const ArgoverseLog log(first);
  EXPECT_EQ(log.sweepCount(), 100u);  // 10 s at 10 Hz
  EXPECT_EQ(log.city(), "SIM");
  const auto stamp = fs::last_write_time(first / "city_SE3_egovehicle.feather");
  const fs::path second = demoLogPath();
  EXPECT_EQ(second, first);
  EXPECT_EQ(fs::last_write_time(second / "city_SE3_egovehicle.feather"), stamp);
  // Nothing temporary left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(cache), fs::directory_iterator()), 1);
  ::unsetenv("HDPRIOR_CACHE_DIR");
}

}  // namespace
}  // namespace hdprior
