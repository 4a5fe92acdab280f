#include "engine/io/ego_poses.h"

#include <cmath>

#include "engine/error.h"
#include "engine/io/feather.h"

namespace hdprior {
using arrow::Column;
using arrow::Type;

namespace {

const char* const kPoseColumns[] = {"qw", "qx", "qy", "qz", "tx_m", "ty_m", "tz_m"};

// Rows of the seven pose columns as transforms, checked for nulls, NaN and zero quaternions.
std::vector<SE3> readPoseColumns(const arrow::Table& t, const std::string& source) {
  std::vector<std::span<const double>> c;
  for (const char* name : kPoseColumns) {
    const Column& col = t.column(name, Type::Float64, source);
    if (col.nullCount() > 0) throw Error(source, std::string("column '") + name + "' has null values");
    c.push_back(col.as<double>());
  }
  std::vector<SE3> poses;
  poses.reserve(static_cast<size_t>(t.numRows));
  for (size_t i = 0; i < static_cast<size_t>(t.numRows); ++i) {
    const Eigen::Quaterniond q(c[0][i], c[1][i], c[2][i], c[3][i]);
    const Eigen::Vector3d tr(c[4][i], c[5][i], c[6][i]);
    if (!q.coeffs().allFinite() || !tr.allFinite()) throw Error(source, "row " + std::to_string(i) + " is not finite");
    if (std::abs(q.norm() - 1.0) > 1e-3) {
      throw Error(source, "row " + std::to_string(i) + " has a non-unit quaternion (norm " + std::to_string(q.norm()) + ")");
    }
    poses.push_back(makeSE3(q, tr));
  }
  return poses;
}

std::vector<Column> poseColumns(const std::vector<SE3>& poses) {
  std::vector<std::vector<double>> v(7, std::vector<double>(poses.size()));
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Quaterniond q(poses[i].rotation());
    const Eigen::Vector3d t = poses[i].translation();
    const double row[7] = {q.w(), q.x(), q.y(), q.z(), t.x(), t.y(), t.z()};
    for (int k = 0; k < 7; ++k) v[k][i] = row[k];
  }
  std::vector<Column> cols;
  for (int k = 0; k < 7; ++k) cols.push_back(Column::fromValues<double>(kPoseColumns[k], Type::Float64, v[k]));
  return cols;
}

}  // namespace

PoseTrajectory readEgoPoses(const std::filesystem::path& path) {
  const std::string source = path.string();
  const arrow::Table t = arrow::readFeather(path);
  const Column& ts = t.column("timestamp_ns", Type::Int64, source);
  if (ts.nullCount() > 0) throw Error(source, "column 'timestamp_ns' has null values");
  if (t.numRows == 0) throw Error(source, "has no poses");
  const auto stamps = ts.as<int64_t>();
  return PoseTrajectory({stamps.begin(), stamps.end()}, readPoseColumns(t, source), source);
}

void writeEgoPoses(const std::filesystem::path& path, const PoseTrajectory& cityTEgo) {
  arrow::Table t;
  t.numRows = static_cast<int64_t>(cityTEgo.size());
  t.columns.push_back(Column::fromValues<int64_t>("timestamp_ns", Type::Int64, cityTEgo.timestamps()));
  for (Column& c : poseColumns(cityTEgo.poses())) t.columns.push_back(std::move(c));
  arrow::writeFeather(path, t);
}

SensorCalibration readSensorCalibration(const std::filesystem::path& path) {
  const std::string source = path.string();
  const arrow::Table t = arrow::readFeather(path);
  const Column& names = t.column("sensor_name", Type::Utf8, source);
  const std::vector<SE3> poses = readPoseColumns(t, source);
  SensorCalibration calib;
  for (int64_t i = 0; i < t.numRows; ++i) {
    if (!names.isValid(i)) throw Error(source, "sensor_name is null in row " + std::to_string(i));
    calib[std::string(names.stringAt(i))] = poses[static_cast<size_t>(i)];
  }
  return calib;
}

void writeSensorCalibration(const std::filesystem::path& path, const SensorCalibration& egoTSensor) {
  std::vector<std::string> names;
  std::vector<SE3> poses;
  for (const auto& [name, pose] : egoTSensor) {
    names.push_back(name);
    poses.push_back(pose);
  }
  arrow::Table t;
  t.numRows = static_cast<int64_t>(names.size());
  t.columns.push_back(Column::fromStrings("sensor_name", names));
  for (Column& c : poseColumns(poses)) t.columns.push_back(std::move(c));
  arrow::writeFeather(path, t);
}

}  // namespace hdprior
