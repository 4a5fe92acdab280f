// Road points against the simulator's per-point labels: precision and recall over simulated towns.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/io/argoverse_log.h"
#include "engine/io/feather.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/road_points.h"
#include "engine/lidar/sweep_points.h"
#include "engine/sim/log_writer.h"
#include "engine/sim/scene.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

std::vector<uint8_t> readLabels(const fs::path& log, int64_t ts) {
  const arrow::Table t = arrow::readFeather(log / "sensors" / "lidar_labels" / (std::to_string(ts) + ".feather"));
  const auto v = t.column("label", arrow::Type::UInt8, "labels").as<uint8_t>();
  return {v.begin(), v.end()};
}

struct Counts {
  size_t truePositive = 0, falsePositive = 0, falseNegative = 0;
  size_t onSidewalk = 0, onOtherGround = 0, onObjects = 0;  // where the false positives are
  double precision() const { return double(truePositive) / double(truePositive + falsePositive); }
  double recall() const { return double(truePositive) / double(truePositive + falseNegative); }
};

// Every `step`-th sweep of a simulated town drive; recall counts the road returns within the
// extractor's range.
Counts measure(uint64_t town, size_t step) {
  SimulationOptions sim;
  sim.townSeed = town;
  sim.seed = town;
  sim.seconds = 6.0;
  sim.outDir = test::freshOutputDir("road_points_sim_" + std::to_string(town));
  const ArgoverseLog log(simulateLog(sim).dir);
  const RoadPointOptions options;
  Counts c;
  for (size_t i = 0; i < log.sweepCount(); i += step) {
    const auto sweep = log.sweep(i);
    const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
    const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*sweep), segmentGround(points), options);
    const std::vector<uint8_t> labels = readLabels(log.dir(), log.sweepTimestamps()[i]);
    for (size_t j = 0; j < points.size(); ++j) {
      const bool isRoad = labels[j] == uint8_t(PointLabel::Road);
      if (road[j]) {
        ++(isRoad ? c.truePositive : c.falsePositive);
        if (labels[j] == uint8_t(PointLabel::SidewalkCurb)) ++c.onSidewalk;
        if (labels[j] == uint8_t(PointLabel::OtherGround)) ++c.onOtherGround;
        if (labels[j] == uint8_t(PointLabel::Object)) ++c.onObjects;
      } else if (isRoad && points[j].head<2>().norm() <= options.maxRange) {
        ++c.falseNegative;
      }
    }
  }
  return c;
}

}  // namespace

TEST(RoadPointsSim, PrecisionAndRecallAgainstSimulatorLabels) {
  for (uint64_t town : {1, 2, 3}) {
    const Counts c = measure(town, 10);
    std::printf("town %llu: road points precision %.4f, recall %.4f (false positives: %zu sidewalk/curb, %zu other ground, "
                "%zu objects)\n", (unsigned long long)town, c.precision(), c.recall(), c.onSidewalk, c.onOtherGround, c.onObjects);
    EXPECT_GT(c.precision(), 0.93) << "town " << town;
    EXPECT_GT(c.recall(), 0.8) << "town " << town;
  }
}

}  // namespace hdprior
