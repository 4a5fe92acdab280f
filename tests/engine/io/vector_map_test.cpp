#include "engine/io/vector_map.h"

#include <gtest/gtest.h>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/sim2.h"
#include "test_data.h"

namespace hdprior {
namespace {

std::filesystem::path vectorMapFile() {
  return test::sharedLog() / "map" / "log_map_archive_7fab2350-7eaf-3b7e-a39d-6937a4c1bede____PIT_city_47896.json";
}

TEST(VectorMap, ReadsRealMapCounts) {
  const VectorMap m = readVectorMap(vectorMapFile());
  EXPECT_EQ(m.drivableAreas.size(), 13u);
  EXPECT_EQ(m.laneSegments.size(), 183u);
  EXPECT_EQ(m.pedestrianCrossings.size(), 11u);
  for (const DrivableArea& a : m.drivableAreas) EXPECT_GE(a.areaBoundary.size(), 3u);
  const auto lane = std::find_if(m.laneSegments.begin(), m.laneSegments.end(),
                                 [](const LaneSegment& l) { return l.id == 38109167; });
  ASSERT_NE(lane, m.laneSegments.end());
  EXPECT_TRUE(lane->isIntersection);
  EXPECT_EQ(lane->laneType, "VEHICLE");
  EXPECT_EQ(lane->successors, std::vector<int64_t>{38109400});
  EXPECT_EQ(lane->predecessors, std::vector<int64_t>{38117100});
  EXPECT_FALSE(lane->rightNeighborId.has_value());
  EXPECT_EQ(lane->leftNeighborId, 38109519);
  EXPECT_DOUBLE_EQ(lane->leftLaneBoundary[0].x(), 5272.94);
}

TEST(VectorMap, JsonRoundTrip) {
  const VectorMap a = readVectorMap(vectorMapFile());
  const VectorMap b = parseVectorMap(vectorMapToJson(a), "mem");
  ASSERT_EQ(b.drivableAreas.size(), a.drivableAreas.size());
  ASSERT_EQ(b.laneSegments.size(), a.laneSegments.size());
  for (size_t i = 0; i < a.drivableAreas.size(); ++i) {
    EXPECT_EQ(b.drivableAreas[i].areaBoundary, a.drivableAreas[i].areaBoundary);
  }
  for (size_t i = 0; i < a.laneSegments.size(); ++i) {
    EXPECT_EQ(b.laneSegments[i].successors, a.laneSegments[i].successors);
    EXPECT_EQ(b.laneSegments[i].leftNeighborId, a.laneSegments[i].leftNeighborId);
    EXPECT_EQ(b.laneSegments[i].rightLaneBoundary, a.laneSegments[i].rightLaneBoundary);
  }
  EXPECT_EQ(vectorMapToJson(b), vectorMapToJson(a));
}

TEST(VectorMap, RejectsBadMapsNamingTheElement) {
  const auto reason = [](const std::string& json) {
    try {
      parseVectorMap(json, "m.json");
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), "m.json");
      return e.reason();
    }
    return std::string("no error");
  };
  const std::string empty = R"("lane_segments": {}, "pedestrian_crossings": {})";
  EXPECT_NE(reason("{").find("invalid JSON"), std::string::npos);
  EXPECT_NE(reason("[]").find("not an object"), std::string::npos);
  EXPECT_NE(reason(R"({"lane_segments": {}, "pedestrian_crossings": {}})").find("drivable_areas"), std::string::npos);
  EXPECT_NE(reason(R"({"drivable_areas": {"7": {"id": 7, "area_boundary": [{"x":1,"y":2,"z":3},{"x":1,"y":3,"z":3}]}}, )" +
                   empty + "}")
                .find("drivable area 7 has 2 vertices"),
            std::string::npos);
  EXPECT_NE(reason(R"({"drivable_areas": {"7": {"id": 7, "area_boundary": [{"x":"a","y":2,"z":3}]}}, )" + empty + "}")
                .find("area_boundary[0].x is not a number"),
            std::string::npos);
}

TEST(Sim2, ReadsRealSim2AndMapsCityToImage) {
  const Sim2 s = readSim2(test::sharedLog() / "map" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede___img_Sim2_city.json");
  EXPECT_EQ(s.t.x(), -5072.400390625);
  EXPECT_EQ(s.t.y(), -2283.900390625);
  EXPECT_DOUBLE_EQ(s.s, 10.0 / 3.0);
  EXPECT_TRUE(s.R.isIdentity());
  const Eigen::Vector2d p(5172.668216028519, 2300.0);
  EXPECT_NEAR((s.imageToCity(s.cityToImage(p)) - p).norm(), 0, 1e-9);
  EXPECT_NEAR(s.cityToImage(p).x(), (5172.668216028519 - 5072.400390625) * 10 / 3, 1e-9);
  EXPECT_THROW(parseSim2(R"({"R":[1,0,0,1],"t":[0,0],"s":0})", "x"), Error);
  EXPECT_THROW(parseSim2(R"({"R":[2,0,0,1],"t":[0,0],"s":1})", "x"), Error);
  EXPECT_THROW(parseSim2(R"({"R":[1,0,0],"t":[0,0],"s":1})", "x"), Error);
  EXPECT_EQ(parseSim2(sim2ToJson(s), "x").t, s.t);
}

}  // namespace
}  // namespace hdprior
