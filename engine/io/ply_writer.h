#pragma once
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

// Binary little-endian PLY with float x, y, z and, when given (same length), float intensity;
// readable by PCL and CloudCompare. Written atomically.
void writePly(const std::filesystem::path& path, const std::vector<Eigen::Vector3f>& points,
              const std::vector<float>& intensity = {});

}  // namespace hdprior
