#include <gtest/gtest.h>

#include <fstream>

#include "engine/io/partial_folder.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

TEST(PartialFolder, PublishReplacesTheFinalFolderWhole) {
  const fs::path dir = test::freshOutputDir("partial_folder");
  fs::create_directories(dir / "run" / "old");
  std::ofstream(dir / "run" / "stale.txt") << "old";
  {
    PartialFolder folder(dir / "run");
    EXPECT_EQ(folder.path(), dir / ".run.partial");
    std::ofstream(folder.path() / "new.txt") << "new";
    EXPECT_TRUE(fs::exists(dir / "run" / "stale.txt"));  // untouched until published
    EXPECT_EQ(folder.publish(), dir / "run");
  }
  EXPECT_TRUE(fs::exists(dir / "run" / "new.txt"));
  EXPECT_FALSE(fs::exists(dir / "run" / "stale.txt"));
  EXPECT_FALSE(fs::exists(dir / ".run.partial"));
}

TEST(PartialFolder, DroppedUnpublishedLeavesNothingAndKeepsTheOldFolder) {
  const fs::path dir = test::freshOutputDir("partial_folder_dropped");
  fs::create_directories(dir / "run");
  fs::create_directories(dir / ".run.partial" / "leftover");  // from an attempt that was killed
  {
    PartialFolder folder(dir / "run");
    EXPECT_FALSE(fs::exists(folder.path() / "leftover"));
    std::ofstream(folder.path() / "half.txt") << "half";
  }
  EXPECT_FALSE(fs::exists(dir / ".run.partial"));
  EXPECT_TRUE(fs::is_directory(dir / "run"));
}

}  // namespace hdprior
