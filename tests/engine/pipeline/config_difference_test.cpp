#include <gtest/gtest.h>

#include "engine/pipeline/config_difference.h"

namespace hdprior {
namespace {

TEST(ConfigDifference, NamesEachChangedKeyWithBothValues) {
  Config a = defaultConfig(), b = a;
  EXPECT_TRUE(configDifferences(a, b).empty());
  b.match.outlierRatio = 0.3;
  b.match.cellSizes = {2.0, 1.0};
  const std::vector<std::string> d = configDifferences(a, b);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NE(d[0].find("match.cell_sizes [4.0,2.0,1.0] -> [2.0,1.0]"), std::string::npos) << d[0];
  EXPECT_EQ(d[1].rfind("match.outlier_ratio ", 0), 0u) << d[1];
  EXPECT_NE(d[1].find("-> 0.3"), std::string::npos) << d[1];
}

}  // namespace
}  // namespace hdprior
