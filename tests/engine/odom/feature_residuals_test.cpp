#include <gtest/gtest.h>

#include <ceres/ceres.h>

#include "engine/odom/feature_registration.h"
#include "engine/odom/feature_residuals.h"

namespace hdprior {
namespace {

SE3 somePose() {
  SE3 T = SE3::Identity();
  T.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, -0.4, 1).normalized()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(1.5, -2.0, 0.3);
  return T;
}

// Residual value and autodiff Jacobian against central differences, at delta != 0.
template <typename Functor, int N>
void expectJacobianMatchesNumeric(const Functor& f) {
  const double delta[6] = {0.05, -0.02, 0.01, 0.02, -0.03, 0.04};
  ceres::AutoDiffCostFunction<Functor, N, 6> cost(new Functor(f));
  double r[N], J[N * 6];
  const double* params[] = {delta};
  double* jacobians[] = {J};
  ASSERT_TRUE(cost.Evaluate(params, r, jacobians));
  for (int k = 0; k < 6; ++k) {
    double plus[6], minus[6], rp[N], rm[N];
    std::copy(delta, delta + 6, plus);
    std::copy(delta, delta + 6, minus);
    plus[k] += 1e-6;
    minus[k] -= 1e-6;
    f(plus, rp);
    f(minus, rm);
    for (int i = 0; i < N; ++i) EXPECT_NEAR(J[i * 6 + k], (rp[i] - rm[i]) / 2e-6, 1e-6) << "row " << i << " col " << k;
  }
}

}  // namespace

TEST(FeatureResiduals, PointToPlaneIsTheSignedDistance) {
  const SE3 base = somePose();
  const Eigen::Vector3d p(2, 1, -0.5);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 2).normalized();
  const PointToPlaneResidual f{p, n, -1.0, base};
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  double r;
  f(zero, &r);
  EXPECT_NEAR(r, n.dot(base * p) - 1.0, 1e-12);
  expectJacobianMatchesNumeric<PointToPlaneResidual, 1>(f);
}

TEST(FeatureResiduals, RotationVectorMatchesAngleAxis) {
  const double w[3] = {0.1, -0.2, 0.3};
  const Eigen::Vector3d p(1, 2, 3);
  const Eigen::Vector3d expected = Eigen::AngleAxisd(Eigen::Vector3d(0.1, -0.2, 0.3).norm(), Eigen::Vector3d(0.1, -0.2, 0.3).normalized()) * p;
  EXPECT_TRUE(rotateByVector<double>(w, p).isApprox(expected, 1e-12));
}

TEST(FeatureFits, PlaneFromNeighbours) {
  Eigen::Vector3f line[5], plane[5];
  for (int i = 0; i < 5; ++i) {
    line[i] = Eigen::Vector3f(1, 2, 0.3f * i);
    plane[i] = Eigen::Vector3f(0.3f * i, 0.7f * (i % 2), 4.f);
  }
  Eigen::Vector3d n;
  double d;
  ASSERT_TRUE(fitPlane(plane, 5, n, d));
  EXPECT_NEAR(std::abs(n.z()), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(d), 4.0, 1e-6);
  EXPECT_FALSE(fitPlane(line, 5, n, d));  // collinear: no plane
}

}  // namespace hdprior
