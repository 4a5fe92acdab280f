#include <gtest/gtest.h>

#include <fstream>

#include "engine/error.h"
#include "engine/io/log_discovery.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

void fakeLog(const fs::path& dir) {
  fs::create_directories(dir / "sensors" / "lidar");
  std::ofstream(dir / "city_SE3_egovehicle.feather") << "x";
}

}  // namespace

TEST(LogDiscovery, FindsLogsAtAnyDepthSortedAndSkipsHiddenAndIncompleteFolders) {
  const fs::path root = test::freshOutputDir("log_discovery");
  fakeLog(root / "b" / "log2");
  fakeLog(root / "a" / "deep" / "er" / "log1");
  fakeLog(root / "c");
  fakeLog(root / "c" / "inner");        // inside a log: not looked at
  fakeLog(root / ".x.partial");         // the simulator's unfinished output
  fs::create_directories(root / "d" / "sensors" / "lidar");  // no poses
  std::ofstream(root / "file.txt") << "x";
  const auto logs = findArgoverseLogs(root);
  ASSERT_EQ(logs.size(), 3u);
  EXPECT_EQ(logs[0], root / "a" / "deep" / "er" / "log1");
  EXPECT_EQ(logs[1], root / "b" / "log2");
  EXPECT_EQ(logs[2], root / "c");
  EXPECT_EQ(findArgoverseLogs(root / "c"), std::vector<fs::path>{root / "c"});  // a log itself
  EXPECT_TRUE(findArgoverseLogs(root / "d").empty());
  EXPECT_THROW(findArgoverseLogs(root / "missing"), Error);
  EXPECT_THROW(findArgoverseLogs(root / "file.txt"), Error);
}

TEST(LogDiscovery, FollowsSymlinkedFoldersOnceEvenInACycle) {
  const fs::path root = test::freshOutputDir("log_discovery_links");
  fakeLog(root / "elsewhere" / "log1");
  fs::create_directories(root / "set");
  fs::create_directory_symlink(root / "elsewhere" / "log1", root / "set" / "linked");
  fs::create_directory_symlink(root / "set", root / "set" / "loop");  // would recurse forever
  EXPECT_EQ(findArgoverseLogs(root / "set"), std::vector<fs::path>{root / "set" / "linked"});
  fakeLog(root / "set" / "real");
  const auto logs = findArgoverseLogs(root / "set");
  ASSERT_EQ(logs.size(), 2u);
  EXPECT_EQ(logs[0], root / "set" / "linked");
  EXPECT_EQ(logs[1], root / "set" / "real");
}

}  // namespace hdprior
