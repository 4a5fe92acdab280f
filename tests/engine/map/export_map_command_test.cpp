// `hdprior export-map`: GeoTIFFs that gdalinfo places correctly in city metres, and bad
// input answered with one line on stderr, exit status 2 and no output files.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "engine/io/file_bytes.h"
#include "engine/map/geotiff.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

nlohmann::json gdalinfo(const fs::path& file) {
  const std::string cmd = "gdalinfo -json '" + file.string() + "' 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run gdalinfo");
  std::string out;
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe.get())) out.append(buffer.data(), n);
  return nlohmann::json::parse(out);
}

void expectGeometry(const nlohmann::json& info, int cols, int rows, double pixel, double left, double top,
                    const std::string& type) {
  EXPECT_EQ(info["size"][0].get<int>(), cols);
  EXPECT_EQ(info["size"][1].get<int>(), rows);
  const auto& gt = info["geoTransform"];
  EXPECT_NEAR(gt[0].get<double>(), left, 1e-6);
  EXPECT_NEAR(gt[1].get<double>(), pixel, 1e-12);
  EXPECT_EQ(gt[2].get<double>(), 0.0);
  EXPECT_NEAR(gt[3].get<double>(), top, 1e-6);
  EXPECT_EQ(gt[4].get<double>(), 0.0);
  EXPECT_NEAR(gt[5].get<double>(), -pixel, 1e-12);
  EXPECT_EQ(info["bands"][0]["type"].get<std::string>(), type);
}

TEST(ExportMapCommand, WritesGeoTiffsThatGdalPlacesInCityMetres) {
  const fs::path out = test::freshOutputDir("export_map") / "tifs";
  const test::CommandResult r = test::runHdprior("export-map '" + test::sharedLog().string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("drivable.tif"), std::string::npos) << r.out;

  // The drivable extent is x 4949.58..5460.00, y 2190.00..2580.00; with the 10 m margin
  // snapped to 0.1 m: x 4939.5..5470.0, y 2180.0..2590.0.
  expectGeometry(gdalinfo(out / "drivable.tif"), 5305, 4100, 0.1, 4939.5, 2590.0, "Byte");
  expectGeometry(gdalinfo(out / "boundary_distance.tif"), 5305, 4100, 0.1, 4939.5, 2590.0, "Float32");
  // The ground-height raster: 880 x 785 pixels of 0.3 m from the Sim2 t = (-5072.400390625, -2283.900390625).
  const nlohmann::json height = gdalinfo(out / "ground_height.tif");
  expectGeometry(height, 880, 785, 0.3, 5072.400390625, 2283.900390625 + 785 * 0.3, "Float32");
  EXPECT_EQ(height["bands"][0]["noDataValue"].get<std::string>(), "NaN");

  // Pixel content in place: the first pose of the log (5172.67, ...) is drivable, and a
  // corner of the raster (inside the margin) is not.
  const GeoRaster<float> drivable = readGeoTiffFloat(out / "drivable.tif");
  const GeoRaster<float> sdf = readGeoTiffFloat(out / "boundary_distance.tif");
  const auto pixelOf = [&](double x, double y) {
    const int col = int(std::floor((x - drivable.transform[0]) / drivable.transform[1]));
    const int row = int(std::floor((y - drivable.transform[3]) / drivable.transform[5]));
    return size_t(row) * size_t(drivable.cols) + size_t(col);
  };
  EXPECT_EQ(drivable.values[pixelOf(5200.0, 2400.0)], 1.0f);
  EXPECT_LT(sdf.values[pixelOf(5200.0, 2400.0)], 0.0f);
  EXPECT_EQ(drivable.values[pixelOf(4940.0, 2589.0)], 0.0f);
  EXPECT_GT(sdf.values[pixelOf(4940.0, 2589.0)], 5.0f);
  for (const char* name : {"drivable.tif", "ground_height.tif", "boundary_distance.tif"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 3);  // no temporaries left
}

TEST(ExportMapCommand, CoarserResolutionOption) {
  const fs::path out = test::freshOutputDir("export_map_coarse") / "tifs";
  const test::CommandResult r =
      test::runHdprior("export-map '" + test::sharedLog().string() + "' --out '" + out.string() + "' --resolution 0.5");
  ASSERT_EQ(r.status, 0) << r.err;
  // x: floor((4949.58 - 10) / 0.5) * 0.5 = 4939.5 .. ceil(5470 / 0.5) * 0.5 = 5470: 1061 columns.
  expectGeometry(gdalinfo(out / "drivable.tif"), 1061, 820, 0.5, 4939.5, 2590.0, "Byte");
}

// A copy of the shared log (map, poses, calibration, sweeps) whose vector map we can corrupt.
fs::path copyOfLog(const std::string& name) {
  const fs::path dir = test::freshOutputDir(name) / "log";
  fs::copy(test::sharedLog(), dir, fs::copy_options::recursive);
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    fs::permissions(e.path(), fs::perms::owner_write, fs::perm_options::add);
  }
  return dir;
}

fs::path vectorMapIn(const fs::path& log) {
  for (const auto& e : fs::directory_iterator(log / "map")) {
    if (e.path().filename().string().starts_with("log_map_archive_")) return e.path();
  }
  throw std::runtime_error("no vector map");
}

TEST(ExportMapCommand, BadInputGivesOneLineAndExitTwoAndNoOutput) {
  const fs::path log = copyOfLog("export_map_bad");
  const fs::path map = vectorMapIn(log);
  const std::string original = readFileText(map);
  auto json = nlohmann::json::parse(original);
  const std::string firstArea = json["drivable_areas"].begin().key();

  struct Case {
    const char* name;
    std::string text;
    std::string mentions;
  };
  std::vector<Case> cases;
  {
    auto j = json;
    auto& boundary = j["drivable_areas"][firstArea]["area_boundary"];
    boundary.erase(boundary.begin() + 2, boundary.end());
    cases.push_back({"two vertices", j.dump(), "needs at least 3"});
  }
  {
    std::string text = json.dump();
    const size_t at = text.find("\"x\":", text.find("\"area_boundary\""));
    const size_t end = text.find_first_of(",}", at);
    text.replace(at + 4, end - at - 4, "NaN");
    cases.push_back({"NaN coordinate", text, map.string()});
  }
  {
    auto j = json;
    j["drivable_areas"] = nlohmann::json::object();
    cases.push_back({"no drivable areas", j.dump(), "no drivable areas"});
  }
  {
    auto j = json;
    auto& boundary = j["drivable_areas"][firstArea]["area_boundary"];
    for (size_t i = 0; i < boundary.size(); ++i) boundary[i]["y"] = boundary[i]["x"];  // collinear
    cases.push_back({"zero-area polygon", j.dump(), "zero area"});
  }
  for (const Case& c : cases) {
    writeFileAtomically(map, c.text);
    const fs::path out = log.parent_path() / "out";
    const test::CommandResult r = test::runHdprior("export-map '" + log.string() + "' --out '" + out.string() + "'");
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.mentions), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(map.filename().string()), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  writeFileAtomically(map, original);

  const fs::path out = log.parent_path() / "out";
  const auto fails = [&](const std::string& args, const std::string& mentions) {
    const test::CommandResult r = test::runHdprior("export-map " + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(mentions), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  };
  fails("'" + log.string() + "'", "--out");
  fails("'" + log.string() + "' --out '" + out.string() + "' --resolution 0", "--resolution");
  fails("'" + log.string() + "' --out '" + out.string() + "' --resolution abc", "--resolution");
  fails("/nonexistent/log --out '" + out.string() + "'", "log directory not found");
  for (const auto& e : fs::directory_iterator(log / "map")) {
    if (e.path().string().find("Sim2") != std::string::npos) fs::remove(e.path());
  }
  fails("'" + log.string() + "' --out '" + out.string() + "'", "Sim2");
}

TEST(ExportMapCommand, UnwritableOutputIsAnError) {
  const fs::path dir = test::freshOutputDir("export_map_unwritable");
  { std::ofstream(dir / "file") << "x"; }
  const test::CommandResult r =
      test::runHdprior("export-map '" + test::sharedLog().string() + "' --out '" + (dir / "file" / "sub").string() + "'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace hdprior
