// changes.geojson and summary.json say what the report found.
#include "engine/changes/change_report_files.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/changes/synthetic_street.h"
#include "engine/map/synthetic_maps.h"

namespace hdprior {
namespace {

TEST(ChangeReportFiles, FeaturesCarryTheVerdictsAndTheSummaryCountsThem) {
  auto world = [](double x, double y) {
    test::GroundPoint g = test::straightStreet(x, y);
    if (y > 0 && std::abs(x) < 3.0) g = {true, true, false};
    return g;
  };
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 3)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(world), map, ChangeOptions{});
  const nlohmann::json geo = nlohmann::json::parse(changesGeoJson(r, "log"));
  EXPECT_EQ(geo["type"], "FeatureCollection");
  int contradicted = 0, missing = 0;
  for (const auto& f : geo["features"]) {
    const auto& p = f["properties"];
    for (const char* key : {"element", "id", "verdict", "confidence", "first_frame", "best_frame", "evidence"})
      EXPECT_TRUE(p.contains(key)) << key;
    EXPECT_EQ(p["element"], "drivable_area");
    if (p["verdict"] == "contradicted") {
      ++contradicted;
      EXPECT_EQ(f["geometry"]["type"], "LineString");
      EXPECT_EQ(p["id"], 1);
      EXPECT_EQ(p["change"], "lane_geometry_change");
    }
    if (p["verdict"] == "missing") {
      ++missing;
      EXPECT_EQ(f["geometry"]["type"], "Polygon");
      EXPECT_TRUE(p["id"].is_null());
      const auto& ring = f["geometry"]["coordinates"][0];
      EXPECT_EQ(ring.front(), ring.back());
    }
  }
  EXPECT_GE(contradicted, 3);
  EXPECT_EQ(missing, 1);
  const nlohmann::json summary = nlohmann::json::parse(changeSummaryJson(r, "log"));
  EXPECT_EQ(summary["drivable_areas"]["contradicted"], 1);
  EXPECT_EQ(summary["contradicted_drivable_areas"], nlohmann::json::array({1}));
  EXPECT_EQ(summary["missing_surfaces"], 1);
}

}  // namespace
}  // namespace hdprior
