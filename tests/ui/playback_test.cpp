#include <gtest/gtest.h>

#include <vector>

#include "ui/playback.h"

namespace hdprior::test {
namespace {

const std::vector<int64_t> kTenHz = {0, 100'000'000, 200'000'000, 300'000'000, 400'000'000};

TEST(Playback, RealTimeFollowsTheTimestampsAtEachSpeed) {
  ui::Playback p;
  p.playing = true;
  EXPECT_EQ(p.advance(0, kTenHz, 0.05), 0u);
  EXPECT_EQ(p.advance(0, kTenHz, 0.06), 1u);  // 0.11 s of log time
  p.speed = 2;                                // 5x
  EXPECT_EQ(p.advance(1, kTenHz, 0.04), 3u);  // 0.01 + 0.2 s
}

TEST(Playback, MaxStepsOneFramePerCallAndStopsAtTheEnd) {
  ui::Playback p;
  p.playing = true;
  p.speed = 3;
  EXPECT_EQ(p.advance(3, kTenHz, 0.0), 4u);
  EXPECT_TRUE(p.playing);
  EXPECT_EQ(p.advance(4, kTenHz, 0.0), 4u);
  EXPECT_FALSE(p.playing);
}

TEST(Playback, PausedDoesNotMove) {
  ui::Playback p;
  EXPECT_EQ(p.advance(1, kTenHz, 10.0), 1u);
}

}  // namespace
}  // namespace hdprior::test
