#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace hdprior {

// One lidar return in the ego frame at the sweep timestamp (Argoverse 2 convention).
struct LidarPoint {
  float x = 0, y = 0, z = 0;
  uint8_t intensity = 0;
  uint8_t laserNumber = 0;  // 0..31 up_lidar, 32..63 down_lidar
  int32_t offsetNs = 0;     // time of the return after the sweep timestamp
};

struct LidarSweep {
  int64_t timestampNs = 0;
  std::vector<LidarPoint> points;
};

// Reads sensors/lidar/<timestamp_ns>.feather (x, y, z float16 or float32; intensity and
// laser_number uint8; offset_ns int32). Throws Error naming the file.
LidarSweep parseLidarSweep(std::span<const uint8_t> bytes, int64_t timestampNs, const std::string& source);
LidarSweep readLidarSweep(const std::filesystem::path& path);
// Writes the Argoverse layout: float16 x/y/z, LZ4_FRAME compressed, atomically.
void writeLidarSweep(const std::filesystem::path& path, const LidarSweep& sweep);

}  // namespace hdprior
