#pragma once
#include <random>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

// A smooth synthetic terrain: a sum of low-frequency plane waves and Gaussian bumps, scaled
// so that its steepest slope over the town is a given grade.
struct HeightField {
  struct Wave {
    Eigen::Vector2d k = Eigen::Vector2d::Zero();  // radians per metre
    double amplitude = 0.0, phase = 0.0;
  };
  struct Bump {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    double amplitude = 0.0, sigma = 1.0;
  };
  std::vector<Wave> waves;
  std::vector<Bump> bumps;
  double base = 0.0;

  double height(const Eigen::Vector2d& p) const;
  Eigen::Vector2d gradient(const Eigen::Vector2d& p) const;
  // sum |A k| + sum |A| / (sigma sqrt(e)): no point has a larger slope.
  double slopeBound() const;

  // The steepest slope at samples `step` apart over the box [min, max].
  double maxSampledSlope(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double step) const;
  // Random hills over the box [min, max], scaled so that maxSampledSlope(min, max, 5) == maxGrade.
  static HeightField random(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double maxGrade,
                            std::mt19937_64& rng);
};

}  // namespace hdprior
