#include "engine/io/ply_writer.h"

#include <bit>
#include <cstring>
#include <string>

#include "engine/error.h"
#include "engine/io/file_bytes.h"

namespace hdprior {

void writePly(const std::filesystem::path& path, const std::vector<Eigen::Vector3f>& points,
              const std::vector<float>& intensity) {
  static_assert(std::endian::native == std::endian::little, "PLY writer assumes a little-endian host");
  const bool withIntensity = !intensity.empty();
  if (withIntensity && intensity.size() != points.size()) {
    throw Error(path.string(), "intensity count differs from point count");
  }
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment hdprior\nelement vertex " +
                       std::to_string(points.size()) + "\nproperty float x\nproperty float y\nproperty float z\n";
  if (withIntensity) header += "property float intensity\n";
  header += "end_header\n";
  const size_t stride = withIntensity ? 16 : 12;
  std::vector<uint8_t> bytes(header.size() + points.size() * stride);
  std::memcpy(bytes.data(), header.data(), header.size());
  uint8_t* out = bytes.data() + header.size();
  for (size_t i = 0; i < points.size(); ++i, out += stride) {
    std::memcpy(out, points[i].data(), 12);
    if (withIntensity) std::memcpy(out + 12, &intensity[i], 4);
  }
  writeFileAtomically(path, bytes);
}

}  // namespace hdprior
