// The `hdprior info` command on the real log, and its answer to bad input: one line on
// stderr naming the file and the problem, exit status 2.
#include <gtest/gtest.h>

#include <fstream>

#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

const char* const kSweep = "sensors/lidar/315966265259836000.feather";

fs::path copyOfSharedLog(const std::string& name) {
  const fs::path dir = test::freshOutputDir(name) / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede";
  fs::copy(test::sharedLog(), dir, fs::copy_options::recursive);
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    fs::permissions(e.path(), fs::perms::owner_write, fs::perm_options::add);
  }
  fs::permissions(dir, fs::perms::owner_write, fs::perm_options::add);
  return dir;
}

void expectOneLineError(const test::CommandResult& r, const std::string& mentions) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(mentions), std::string::npos) << "expected '" << mentions << "' in: " << r.err;
}

TEST(InfoCommand, SummarisesRealLog) {
  const test::CommandResult r = test::runHdprior("info '" + test::sharedLog().string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("7fab2350-7eaf-3b7e-a39d-6937a4c1bede"), std::string::npos);
  EXPECT_NE(r.out.find("city:              PIT"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sweeps:            2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("poses:             2706"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("drivable areas:    13"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lane segments:     183"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ped. crossings:    11"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("785 rows x 880 cols, 0.300 m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("first sweep:       99229 points"), std::string::npos) << r.out;
}

TEST(InfoCommand, MissingLogAndBadOptions) {
  expectOneLineError(test::runHdprior("info /nonexistent/log"), "/nonexistent/log: log directory not found");
  expectOneLineError(test::runHdprior("info"), "argument LOG: is required");
  expectOneLineError(test::runHdprior("info '" + test::sharedLog().string() + "' extra"), "argument 'extra': not expected");
  expectOneLineError(test::runHdprior("info '" + test::sharedLog().string() + "' --bogus"), "option --bogus: unknown option");
  expectOneLineError(test::runHdprior("nosuchcommand"), "unknown command");
}

TEST(InfoCommand, MissingFiles) {
  const fs::path log = copyOfSharedLog("info_missing");
  fs::remove(log / "city_SE3_egovehicle.feather");
  expectOneLineError(test::runHdprior("info '" + log.string() + "'"), "city_SE3_egovehicle.feather: file not found");
  fs::remove_all(log / "map");
  fs::copy(test::sharedLog() / "city_SE3_egovehicle.feather", log / "city_SE3_egovehicle.feather");
  expectOneLineError(test::runHdprior("info '" + log.string() + "'"), "map folder not found");
}

TEST(InfoCommand, TruncatedSweep) {
  const fs::path log = copyOfSharedLog("info_truncated");
  fs::resize_file(log / kSweep, 5000);
  expectOneLineError(test::runHdprior("info '" + log.string() + "'"), "315966265259836000.feather: ");
}

TEST(InfoCommand, CorruptFiles) {
  const fs::path log = copyOfSharedLog("info_corrupt");
  for (const char* file : {kSweep, "city_SE3_egovehicle.feather", "calibration/egovehicle_SE3_sensor.feather"}) {
    std::vector<uint8_t> bytes = readFileBytes(test::sharedLog() / file);
    for (size_t i = bytes.size() - 400; i < bytes.size() - 10; ++i) bytes[i] ^= 0x5a;  // footer area
    writeFileAtomically(log / file, bytes);
    expectOneLineError(test::runHdprior("info '" + log.string() + "'"), fs::path(file).filename().string() + ": ");
    fs::copy_file(test::sharedLog() / file, log / file, fs::copy_options::overwrite_existing);
  }
  const fs::path npy = log / "map" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede_ground_height_surface____PIT.npy";
  fs::resize_file(npy, 1000);
  expectOneLineError(test::runHdprior("info '" + log.string() + "'"), "____PIT.npy: truncated");
  fs::copy_file(test::sharedLog() / "map" / npy.filename(), npy, fs::copy_options::overwrite_existing);
  for (const auto& e : fs::directory_iterator(log / "map")) {
    if (e.path().extension() == ".json") {
      fs::permissions(e.path(), fs::perms::owner_write, fs::perm_options::add);
      writeFileAtomically(e.path(), std::string("{\"drivable_areas\": [1, 2"));
      expectOneLineError(test::runHdprior("info '" + log.string() + "'"), "invalid JSON");
      fs::copy_file(test::sharedLog() / "map" / e.path().filename(), e.path(), fs::copy_options::overwrite_existing);
    }
  }
}

TEST(InfoCommand, MistypedColumn) {
  const fs::path log = copyOfSharedLog("info_mistyped");
  arrow::Table poses = arrow::readFeather(log / "city_SE3_egovehicle.feather");
  for (arrow::Column& c : poses.columns) {
    if (c.name == "tx_m") {  // float64 -> int64 with the same bytes: a mistyped column
      c.type = arrow::Type::Int64;
    }
  }
  arrow::writeFeather(log / "city_SE3_egovehicle.feather", poses);
  expectOneLineError(test::runHdprior("info '" + log.string() + "'"), "column 'tx_m' has type int64, expected float64");
}

}  // namespace
}  // namespace hdprior
