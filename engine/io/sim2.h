#pragma once
#include <filesystem>
#include <string>

#include <Eigen/Core>

namespace hdprior {

// Argoverse 2's img_Sim2_city: a city point p maps to image coordinates s * (R p + t).
struct Sim2 {
  Eigen::Matrix2d R = Eigen::Matrix2d::Identity();
  Eigen::Vector2d t = Eigen::Vector2d::Zero();
  double s = 1.0;

  Eigen::Vector2d cityToImage(const Eigen::Vector2d& p) const { return s * (R * p + t); }
  Eigen::Vector2d imageToCity(const Eigen::Vector2d& uv) const { return R.transpose() * (uv / s - t); }
};

// Strict: R must be a rotation, s positive and finite; throws Error naming the source.
Sim2 parseSim2(const std::string& json, const std::string& source);
Sim2 readSim2(const std::filesystem::path& path);
std::string sim2ToJson(const Sim2& sim2);

}  // namespace hdprior
