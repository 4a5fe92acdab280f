#include "engine/eval/trajectory_alignment.h"

#include <cmath>

#include <Eigen/Geometry>

#include "engine/error.h"

namespace hdprior {

std::string alignmentLabel(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::None: return "none (city frame; runs start at the first ground-truth pose)";
    case AlignmentMode::SE3: return "SE(3) Umeyama";
    case AlignmentMode::Sim3: return "Sim(3) Umeyama";
    case AlignmentMode::FourDof: return "4-DOF (yaw + translation)";
  }
  return "?";
}

AlignmentMode parseAlignmentMode(const std::string& name) {
  if (name == "none") return AlignmentMode::None;
  if (name == "se3") return AlignmentMode::SE3;
  if (name == "sim3") return AlignmentMode::Sim3;
  if (name == "4dof") return AlignmentMode::FourDof;
  throw Error("alignment", "unknown mode '" + name + "' (none, se3, sim3, 4dof)");
}

std::vector<SE3> Alignment::apply(const std::vector<SE3>& estimate) const {
  std::vector<SE3> out(estimate.size());
  for (size_t i = 0; i < estimate.size(); ++i) {
    out[i].linear() = transform.rotation() * estimate[i].rotation();
    out[i].translation() = scale * (transform.rotation() * estimate[i].translation()) + transform.translation();
  }
  return out;
}

namespace {

Alignment fourDof(const std::vector<SE3>& gt, const std::vector<SE3>& est) {
  Eigen::Vector3d cg = Eigen::Vector3d::Zero(), ce = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < gt.size(); ++i) {
    cg += gt[i].translation();
    ce += est[i].translation();
  }
  cg /= double(gt.size());
  ce /= double(gt.size());
  // Yaw maximising sum of (R e) . g over centred xy positions.
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < gt.size(); ++i) {
    const Eigen::Vector3d g = gt[i].translation() - cg, e = est[i].translation() - ce;
    sxx += e.x() * g.x() + e.y() * g.y();
    sxy += e.x() * g.y() - e.y() * g.x();
  }
  Alignment a;
  a.transform.linear() = Eigen::AngleAxisd(std::atan2(sxy, sxx), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  a.transform.translation() = cg - a.transform.rotation() * ce;
  return a;
}

}  // namespace

Alignment alignTrajectories(const std::vector<SE3>& gt, const std::vector<SE3>& est, AlignmentMode mode) {
  if (gt.size() != est.size() || gt.empty()) throw Error("alignment", "needs matched, non-empty trajectories");
  Alignment a;
  switch (mode) {
    case AlignmentMode::None:
      return a;
    case AlignmentMode::FourDof:
      return fourDof(gt, est);
    case AlignmentMode::SE3:
    case AlignmentMode::Sim3: {
      if (gt.size() < 3) throw Error("alignment", alignmentLabel(mode) + " needs at least 3 poses");
      Eigen::Matrix3Xd src(3, est.size()), dst(3, gt.size());
      for (size_t i = 0; i < gt.size(); ++i) {
        src.col(i) = est[i].translation();
        dst.col(i) = gt[i].translation();
      }
      const Eigen::Matrix4d T = Eigen::umeyama(src, dst, mode == AlignmentMode::Sim3);
      const Eigen::Matrix3d sR = T.topLeftCorner<3, 3>();
      a.scale = mode == AlignmentMode::Sim3 ? std::cbrt(sR.determinant()) : 1.0;
      a.transform.linear() = sR / a.scale;
      a.transform.translation() = T.topRightCorner<3, 1>();
      return a;
    }
  }
  return a;
}

}  // namespace hdprior
