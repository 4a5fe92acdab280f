#pragma once
#include <random>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

// A smooth synthetic terrain: a sum of low-frequency plane waves and Gaussian bumps, scaled
// so that its slope never exceeds a given grade anywhere (the bound is analytic).
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

  // Random hills over the box [min, max], scaled to slopeBound() == maxGrade.
  static HeightField random(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double maxGrade,
                            std::mt19937_64& rng);
};

}  // namespace hdprior
