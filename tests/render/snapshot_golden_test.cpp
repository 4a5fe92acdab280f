#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "render/image_compare.h"
#include "render/layer_registry.h"
#include "render/snapshot.h"
#include "test_data.h"

namespace hdprior::test {
namespace {

// The shared log and its map, loaded once for all golden tests.
class SnapshotGolden : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    log_ = std::make_unique<ArgoverseLog>(sharedLog());
    map_ = std::make_unique<HdMap>(HdMap::load(log_->mapFiles(), render::renderMapOptions()));
  }
  static void TearDownTestSuite() {
    map_.reset();
    log_.reset();
  }

  static render::Image snapshot(size_t frame, render::View view, const std::string& layers, bool overlay = true) {
    render::SnapshotOptions options{640, 360, view, render::parseLayerList(layers), overlay};
    render::Snapshotter snapshotter(*log_, *map_, options);
    return snapshotter.render(frame);
  }

  static std::unique_ptr<ArgoverseLog> log_;
  static std::unique_ptr<HdMap> map_;
};
std::unique_ptr<ArgoverseLog> SnapshotGolden::log_;
std::unique_ptr<HdMap> SnapshotGolden::map_;

TEST_F(SnapshotGolden, Frame0TopAllLayers) {
  EXPECT_EQ(checkGolden(snapshot(0, render::View::Top, "all"), "frame0_top_all"), "");
}

TEST_F(SnapshotGolden, Frame1TopAllLayers) {
  EXPECT_EQ(checkGolden(snapshot(1, render::View::Top, "all"), "frame1_top_all"), "");
}

TEST_F(SnapshotGolden, Frame0OrbitAllLayers) {
  EXPECT_EQ(checkGolden(snapshot(0, render::View::Orbit, "all"), "frame0_orbit_all"), "");
}

TEST_F(SnapshotGolden, Frame1OrbitSweepAndDrivable) {
  EXPECT_EQ(checkGolden(snapshot(1, render::View::Orbit, "drivable,boundary,sweep,ego"), "frame1_orbit_sweep_drivable"),
            "");
}

TEST_F(SnapshotGolden, Frame0TopMapOnly) {
  EXPECT_EQ(checkGolden(snapshot(0, render::View::Top, "ground,drivable,boundary,lanes"), "frame0_top_map"), "");
}

// The comparison has teeth: switching the sweep off must fail against the all-layers golden.
TEST_F(SnapshotGolden, FailsWhenALayerIsSwitchedOff) {
  if (const char* update = std::getenv("HDPRIOR_UPDATE_GOLDEN"); update && std::string(update) == "1")
    GTEST_SKIP() << "regenerating goldens";
  const std::string result =
      checkGolden(snapshot(0, render::View::Top, "ground,drivable,boundary,lanes,trajectory,ego"), "frame0_top_all");
  EXPECT_NE(result, "");
  EXPECT_NE(result.find("differ"), std::string::npos) << result;
}

TEST_F(SnapshotGolden, SameFrameRendersIdentically) {
  const render::Image a = snapshot(0, render::View::Orbit, "all"), b = snapshot(0, render::View::Orbit, "all");
  const ImageDifference d = compareImages(a, b, 0);
  EXPECT_TRUE(d.sameSize);
  EXPECT_EQ(d.differingPixels, 0u);
}

// Rows top to bottom and north up: the ego (rear axle) is drawn at the image centre, and the
// tip of its white arrow, 3.6 m ahead, is the white pixel farthest from it, in the direction
// of the pose's heading (image y grows southwards). Without the overlay, whose scale bar is white too.
TEST_F(SnapshotGolden, TopViewShowsTheEgoHeadingNorthUp) {
  const render::Image image = snapshot(0, render::View::Top, "ego", false);
  const Eigen::Vector2d centre(image.width / 2.0, image.height / 2.0);
  Eigen::Vector2d tip = centre, red = Eigen::Vector2d::Zero();
  int reds = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      const Eigen::Vector2d at(x + 0.5, y + 0.5);
      if (p[0] > 200 && p[1] > 200 && p[2] > 200 && (at - centre).norm() > (tip - centre).norm()) tip = at;
      if (p[0] > 150 && p[1] < 80) red += at, ++reds;
    }
  ASSERT_GT(reds, 5);
  const Eigen::Vector2d ahead = tip - centre;
  EXPECT_NEAR(ahead.norm(), 3.6 * image.height / 80.0, 3.0);  // 80 m shown vertically
  const Eigen::Vector3d forward = log_->cityTEgo().at(log_->sweepTimestamps()[0]).linear().col(0);
  const Eigen::Vector2d expected = Eigen::Vector2d(forward.x(), -forward.y()).normalized();
  EXPECT_GT(ahead.normalized().dot(expected), 0.95) << "arrow offset " << ahead.transpose();
  EXPECT_LT((red / reds - centre).norm(), 10.0);  // the body is around the middle
}

TEST_F(SnapshotGolden, FrameOutOfRangeThrows) {
  render::Snapshotter snapshotter(*log_, *map_, {64, 64, render::View::Top, {"sweep"}});
  EXPECT_THROW(snapshotter.render(log_->sweepCount()), Error);
}

}  // namespace
}  // namespace hdprior::test
