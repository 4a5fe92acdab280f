#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/eval/trajectory_errors.h"

namespace hdprior {
namespace {

SE3 pose(double x, double y, double z, double yaw) {
  SE3 T = SE3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

// A curvy 3-D drive: 200 poses, 1 m apart, gently turning and climbing.
std::vector<SE3> drive() {
  std::vector<SE3> out;
  double x = 0, y = 0, yaw = 0;
  for (int i = 0; i < 200; ++i) {
    out.push_back(pose(x, y, 0.02 * i + 0.5 * std::sin(i * 0.05), yaw));
    yaw += 0.01 * std::sin(i * 0.03);
    x += std::cos(yaw);
    y += std::sin(yaw);
  }
  return out;
}

PoseTrajectory timed(const std::vector<SE3>& poses, int64_t t0 = 1000000000, int64_t dt = 100000000) {
  std::vector<int64_t> t;
  for (size_t i = 0; i < poses.size(); ++i) t.push_back(t0 + int64_t(i) * dt);
  return PoseTrajectory(t, poses);
}

}  // namespace

TEST(ErrorStats, HandComputed) {
  const ErrorStats s = errorStats({3, 1, 2, 6});
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt((9 + 1 + 4 + 36) / 4.0));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt((0 + 4 + 1 + 9) / 4.0));
  EXPECT_DOUBLE_EQ(s.max, 6.0);
}

TEST(Ate, HandComputedPerFrameErrors) {
  // GT along x; estimate offset by (0, 1, 0), (0, 0, 2) in the GT pose's frame, and yawed 90 deg at
  // frame 2 so its world offset (1, 0, 0) is (0, -1, 0) in the frame: E_i = Q_i^-1 P_i.
  const std::vector<SE3> gt = {pose(0, 0, 0, 0), pose(1, 0, 0, M_PI / 2), pose(2, 0, 0, M_PI / 2)};
  const std::vector<SE3> est = {pose(0, 1, 0, 0), pose(1, 0, 2, M_PI / 2), pose(3, 0, 0, M_PI / 2 + 0.1)};
  const AteResult r = absoluteTrajectoryError(gt, est);
  EXPECT_NEAR(r.translationErrors[0], 1.0, 1e-12);
  EXPECT_NEAR(r.translationErrors[1], 2.0, 1e-12);
  EXPECT_NEAR(r.translationErrors[2], 1.0, 1e-12);
  EXPECT_NEAR(r.rotationErrorsDeg[2], 0.1 * 180 / M_PI, 1e-9);
  EXPECT_NEAR(r.translation.mean, 4.0 / 3, 1e-12);
  EXPECT_NEAR(r.translation.rmse, std::sqrt(6.0 / 3), 1e-12);
  EXPECT_NEAR(r.translation.max, 2.0, 1e-12);
  // Lateral: across the GT heading only (frame 1's offset is vertical, frame 2's is to the right).
  EXPECT_NEAR(r.lateralErrors[0], 1.0, 1e-12);
  EXPECT_NEAR(r.lateralErrors[1], 0.0, 1e-12);
  EXPECT_NEAR(r.lateralErrors[2], 1.0, 1e-12);
  EXPECT_NEAR(r.lateral.rmse, std::sqrt(2.0 / 3), 1e-12);
  // Along: frame 2's offset is along its heading.
  EXPECT_NEAR(r.alongErrors[0], 0.0, 1e-12);
  EXPECT_NEAR(r.alongErrors[1], 0.0, 1e-12);
  EXPECT_NEAR(r.alongErrors[2], 0.0, 1e-12);
}

TEST(Ate, AlongAndLateralAreHorizontalAlongAndAcrossTheHeading) {
  // A rolled and pitched ground-truth pose heading 30 deg: an altitude error has no lateral part, a
  // horizontal offset perpendicular to the heading is all lateral, one along it none.
  SE3 gt = pose(5, 5, 1, M_PI / 6);
  gt.linear() = gt.linear() * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()).toRotationMatrix();  // yaw, pitch, roll
  auto moved = [&](const Eigen::Vector3d& d) {
    SE3 p = gt;
    p.translation() += d;
    return p;
  };
  const Eigen::Vector3d across(-std::sin(M_PI / 6), std::cos(M_PI / 6), 0), along(std::cos(M_PI / 6), std::sin(M_PI / 6), 0);
  const AteResult r = absoluteTrajectoryError({gt, gt, gt}, {moved({0, 0, 0.7}), moved(0.4 * across), moved(0.9 * along)});
  EXPECT_NEAR(r.lateralErrors[0], 0.0, 1e-12);
  EXPECT_NEAR(r.lateralErrors[1], 0.4, 1e-12);
  EXPECT_NEAR(r.lateralErrors[2], 0.0, 1e-12);
  EXPECT_NEAR(r.alongErrors[0], 0.0, 1e-12);
  EXPECT_NEAR(r.alongErrors[1], 0.0, 1e-12);
  EXPECT_NEAR(r.alongErrors[2], 0.9, 1e-12);
  EXPECT_NEAR(r.along.rmse, 0.9 / std::sqrt(3.0), 1e-12);
}

TEST(Alignment, EachModeRecoversItsTransform) {
  const std::vector<SE3> gt = drive();
  SE3 G = SE3::Identity();
  G.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  G.translation() = Eigen::Vector3d(100, -50, 3);
  // est = G^-1 * gt: a yaw + translation; every mode that can model it gives zero error.
  std::vector<SE3> est;
  for (const SE3& q : gt) est.push_back(G.inverse() * q);
  const AteResult none = absoluteTrajectoryError(gt, alignTrajectories(gt, est, AlignmentMode::None).apply(est));
  EXPECT_NEAR(none.translationErrors.front(), (gt.front().translation() - est.front().translation()).norm(), 1e-9);
  for (AlignmentMode mode : {AlignmentMode::SE3, AlignmentMode::Sim3, AlignmentMode::FourDof}) {
    const Alignment a = alignTrajectories(gt, est, mode);
    const AteResult r = absoluteTrajectoryError(gt, a.apply(est));
    EXPECT_LT(r.translation.max, 1e-6) << alignmentLabel(mode);
    EXPECT_LT(r.rotationDeg.max, 1e-6) << alignmentLabel(mode);
  }
  // A scaled copy: only Sim(3) removes it, and it reports the scale.
  std::vector<SE3> scaled;
  for (const SE3& q : est) {
    SE3 s = q;
    s.translation() *= 0.5;
    scaled.push_back(s);
  }
  const Alignment sim = alignTrajectories(gt, scaled, AlignmentMode::Sim3);
  EXPECT_NEAR(sim.scale, 2.0, 1e-9);
  EXPECT_LT(absoluteTrajectoryError(gt, sim.apply(scaled)).translation.max, 1e-6);
  EXPECT_GT(absoluteTrajectoryError(gt, alignTrajectories(gt, scaled, AlignmentMode::SE3).apply(scaled)).translation.max, 1.0);
  // A roll of the whole trajectory: SE(3) removes it, 4-DOF (yaw only) cannot.
  SE3 roll = SE3::Identity();
  roll.linear() = Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()).toRotationMatrix();
  std::vector<SE3> rolled;
  for (const SE3& q : gt) rolled.push_back(roll * q);
  EXPECT_LT(absoluteTrajectoryError(gt, alignTrajectories(gt, rolled, AlignmentMode::SE3).apply(rolled)).translation.max, 1e-6);
  EXPECT_GT(absoluteTrajectoryError(gt, alignTrajectories(gt, rolled, AlignmentMode::FourDof).apply(rolled)).translation.max, 0.1);
}

TEST(Alignment, NoneMeasuresInTheCityFrame) {
  const std::vector<SE3> gt = drive();
  std::vector<SE3> est = gt;
  for (SE3& p : est) p.translation().y() += 0.3;  // a constant offset, even at the start, stays visible
  est.back().translation().x() += 5;
  const AteResult r = absoluteTrajectoryError(gt, alignTrajectories(gt, est, AlignmentMode::None).apply(est));
  EXPECT_NEAR(r.translationErrors.front(), 0.3, 1e-12);
  EXPECT_NEAR(r.translation.max, std::hypot(5.0, 0.3), 1e-9);
}

TEST(Rpe, StraightDriftIsThePercentage) {
  // Estimate travels 1 % too far along a straight line: drift 1 %, no yaw drift.
  std::vector<SE3> gt, est;
  for (int i = 0; i <= 300; ++i) {
    gt.push_back(pose(i, 0, 0, 0));
    est.push_back(pose(1.01 * i, 0, 0, 0));
  }
  const RpeResult r = relativePoseError(gt, est, 100);
  EXPECT_EQ(r.segments, 201u);
  EXPECT_NEAR(r.translationPercent, 1.0, 1e-9);
  EXPECT_NEAR(r.yawDegPer100m, 0.0, 1e-12);
  // A constant yaw rate error of 0.01 deg per metre is 1 deg / 100 m.
  std::vector<SE3> turning;
  for (int i = 0; i <= 300; ++i) turning.push_back(pose(i, 0, 0, 0.01 * i * M_PI / 180));
  EXPECT_NEAR(relativePoseError(gt, turning, 100).yawDegPer100m, 1.0, 1e-9);
}

TEST(Association, InterpolatesAndCountsTimestampsOutsideTheSpan) {
  const PoseTrajectory gt = timed({pose(0, 0, 0, 0), pose(10, 0, 0, 0)}, 0, 1000);
  const PoseTrajectory est = timed({pose(0, 0, 0, 0), pose(5, 0, 0, 0)}, 0, 500);
  const AssociatedPoses a = associateByTime(gt, est);
  ASSERT_EQ(a.gt.size(), 2u);
  EXPECT_NEAR(a.gt[1].translation().x(), 5.0, 1e-12);
  const PoseTrajectory late = timed({pose(0, 0, 0, 0), pose(1, 0, 0, 0), pose(2, 0, 0, 0)}, 500, 600);
  try {
    associateByTime(gt, late);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("2 of 3 estimate timestamps fall outside"), std::string::npos) << e.what();
  }
}

TEST(Evaluation, LabelsAndFullPipeline) {
  const std::vector<SE3> gt = drive();
  std::vector<SE3> est;
  for (const SE3& q : gt) est.push_back(pose(7, 7, 0, 0.2) * q);
  EXPECT_EQ(evaluateTrajectory(timed(gt), timed(est), AlignmentMode::None).label,
            "none (city frame; runs start at the first ground-truth pose)");
  const TrajectoryEvaluation e = evaluateTrajectory(timed(gt), timed(est), AlignmentMode::SE3);
  EXPECT_EQ(e.label, "SE(3) Umeyama");
  EXPECT_LT(e.ate.translation.max, 1e-6);
  EXPECT_GT(e.rpe100.segments, 0u);
  EXPECT_LT(e.rpe100.translationPercent, 1e-6);
  EXPECT_EQ(alignmentLabel(parseAlignmentMode("4dof")), "4-DOF (yaw + translation)");
  EXPECT_THROW(parseAlignmentMode("affine"), Error);
}

}  // namespace hdprior
