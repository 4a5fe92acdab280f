#include <gtest/gtest.h>

#include "engine/eval/axis_ticks.h"

namespace hdprior {

TEST(AxisTicks, RoundOutwardsToNiceSteps) {
  const AxisTicks t = axisTicks(-0.37, 1.9, 4);
  EXPECT_DOUBLE_EQ(t.step, 1.0);
  EXPECT_DOUBLE_EQ(t.low, -1.0);
  EXPECT_DOUBLE_EQ(t.high, 2.0);
  EXPECT_EQ(t.count(), 3);
  EXPECT_EQ(t.decimals, 0);
  const AxisTicks small = axisTicks(0.0, 0.083, 4);
  EXPECT_DOUBLE_EQ(small.step, 0.05);
  EXPECT_DOUBLE_EQ(small.high, 0.1);
  EXPECT_EQ(small.decimals, 2);
  EXPECT_EQ(tickLabel(small.at(1), small.decimals), "0.05");
}

TEST(AxisTicks, ZeroWidthRangeAndNegativeZero) {
  const AxisTicks t = axisTicks(5.0, 5.0, 4);
  EXPECT_LT(t.low, 5.0);
  EXPECT_GT(t.high, 5.0);
  EXPECT_EQ(tickLabel(-1e-17, 1), "0.0");
  EXPECT_DOUBLE_EQ(niceStep(600.0, 12), 50.0);
}

}  // namespace hdprior
