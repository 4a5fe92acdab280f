#include "engine/io/lidar_sweep.h"

#include "engine/error.h"
#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "engine/io/float16.h"

namespace hdprior {
using arrow::Column;
using arrow::Type;

namespace {

// Writes column `name` (float16 or float32, no nulls) into `member` of every point.
void readCoordinate(const arrow::Table& t, const char* name, float LidarPoint::*member, std::vector<LidarPoint>& points,
                    const std::string& source) {
  const Column& c = t.column(name, source);
  if (c.nullCount() > 0) throw Error(source, std::string("column '") + name + "' has null values");
  if (c.type == Type::Float32) {
    const auto v = c.as<float>();
    for (size_t i = 0; i < points.size(); ++i) points[i].*member = v[i];
  } else if (c.type == Type::Float16) {
    const auto v = c.as<uint16_t>();
    for (size_t i = 0; i < points.size(); ++i) points[i].*member = halfToFloat(v[i]);
  } else {
    throw Error(source, std::string("column '") + name + "' has type " + std::string(arrow::typeName(c.type)) +
                            ", expected float16 or float32");
  }
}

int64_t timestampFromName(const std::filesystem::path& path) {
  const std::string stem = path.stem().string();
  try {
    size_t used = 0;
    const long long t = std::stoll(stem, &used);
    if (used == stem.size() && t >= 0) return t;
  } catch (const std::exception&) {
  }
  throw Error(path.string(), "sweep file name is not a nanosecond timestamp");
}

}  // namespace

LidarSweep parseLidarSweep(std::span<const uint8_t> bytes, int64_t timestampNs, const std::string& source) {
  const arrow::Table t = arrow::parseFeather(bytes, source);
  const auto intensity = t.column("intensity", Type::UInt8, source).as<uint8_t>();
  const auto laser = t.column("laser_number", Type::UInt8, source).as<uint8_t>();
  const auto offset = t.column("offset_ns", Type::Int32, source).as<int32_t>();
  LidarSweep sweep{timestampNs, std::vector<LidarPoint>(static_cast<size_t>(t.numRows))};
  readCoordinate(t, "x", &LidarPoint::x, sweep.points, source);
  readCoordinate(t, "y", &LidarPoint::y, sweep.points, source);
  readCoordinate(t, "z", &LidarPoint::z, sweep.points, source);
  for (size_t i = 0; i < sweep.points.size(); ++i) {
    sweep.points[i].intensity = intensity[i];
    sweep.points[i].laserNumber = laser[i];
    sweep.points[i].offsetNs = offset[i];
  }
  return sweep;
}

LidarSweep readLidarSweep(const std::filesystem::path& path) {
  return parseLidarSweep(readFileBytes(path), timestampFromName(path), path.string());
}

void writeLidarSweep(const std::filesystem::path& path, const LidarSweep& sweep) {
  const size_t n = sweep.points.size();
  std::vector<uint16_t> x(n), y(n), z(n);
  std::vector<uint8_t> intensity(n), laser(n);
  std::vector<int32_t> offset(n);
  for (size_t i = 0; i < n; ++i) {
    const LidarPoint& p = sweep.points[i];
    x[i] = floatToHalf(p.x);
    y[i] = floatToHalf(p.y);
    z[i] = floatToHalf(p.z);
    intensity[i] = p.intensity;
    laser[i] = p.laserNumber;
    offset[i] = p.offsetNs;
  }
  arrow::Table t;
  t.numRows = static_cast<int64_t>(n);
  t.columns = {Column::fromValues<uint16_t>("x", Type::Float16, x), Column::fromValues<uint16_t>("y", Type::Float16, y),
               Column::fromValues<uint16_t>("z", Type::Float16, z),
               Column::fromValues<uint8_t>("intensity", Type::UInt8, intensity),
               Column::fromValues<uint8_t>("laser_number", Type::UInt8, laser),
               Column::fromValues<int32_t>("offset_ns", Type::Int32, offset)};
  arrow::writeFeather(path, t, arrow::Compression::Lz4Frame);
}

}  // namespace hdprior
