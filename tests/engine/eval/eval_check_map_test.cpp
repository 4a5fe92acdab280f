// `hdprior eval --check-map`: each log's map check beside its run, scored against the log's
// map_change.json where it has one (a street drawn narrower and a lane line moved, labelled), counted as false alarms
// where it has none (an unchanged map), and both in the table.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"
#include "map_change_labels_file.h"
#include "moved_lane_line.h"
#include "narrowed_street.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

TEST(EvalCheckMap, ScoresTheLabelledLogAndCountsFalseAlarmsOnTheOther) {
  const fs::path dir = test::freshOutputDir("eval_check_map");
  const fs::path changed = test::copySharedTownDrive(1, 7, 8.0, dir / "logs" / "changed");
  const fs::path current = test::copySharedTownDrive(2, 1, 6.0, dir / "logs" / "current");
  const int64_t narrowed = test::narrowStreetAtStart(changed, 2.5);
  const Ring2 moved = test::moveALaneLine(changed, 1.2);
  test::writeMapChangeLabels(changed, {test::changedAreaLabel(changed, narrowed), test::movedLaneLineLabel(moved, 1.2)});
  const fs::path out = dir / "out";
  const test::CommandResult r = test::runHdprior("eval " + test::quoted(dir / "logs") + " --out " + test::quoted(out) + " -j 2 --check-map");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const fs::path& log : {changed, current}) {
    const std::string id = ArgoverseLog(log).id();
    EXPECT_TRUE(fs::exists(out / id / "changes" / "changes.geojson")) << id;
    EXPECT_TRUE(fs::exists(out / id / "changes" / "summary.json")) << id;
    const nlohmann::json result = nlohmann::json::parse(test::readFileText(out / (id + ".result.json")));
    ASSERT_TRUE(result.contains("map_check")) << result.dump();
    EXPECT_EQ(result["map_check"]["labelled"].get<bool>(), log == changed);
  }
  EXPECT_TRUE(fs::exists(out / ArgoverseLog(changed).id() / "changes" / "score.json"));
  const std::string table = test::readFileText(out / "table.md");
  EXPECT_NE(table.find("Map check on 1 logs with labelled map changes"), std::string::npos) << table;
  EXPECT_NE(table.find("1 of 1 changes found (recall 1.00)"), std::string::npos) << table;
  EXPECT_NE(table.find("Map check on 1 logs without labelled changes: 0 reports"), std::string::npos) << table;
  EXPECT_NE(table.find("Lane lines (paint within 8 m of the lidar; a report is a line with contradicted stretches), the same logs with labelled changes: 1 of 1 "
                       "changes found (recall 1.00)"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("Lane lines, the logs without labelled changes: 0 reports"), std::string::npos) << table;
}

}  // namespace
}  // namespace hdprior
