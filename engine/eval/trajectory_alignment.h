#pragma once
#include <string>
#include <vector>

#include "engine/geom/se3.h"

namespace hdprior {

// How an estimated trajectory is put into the ground truth's frame before errors are measured.
// None: no alignment; errors in the city frame (the paper's protocol: runs start at the first
// ground-truth pose, and priors may move even that). SE3 / Sim3: Umeyama least squares on positions (Sim3 also scales).
// FourDof: yaw + translation, the right one for gravity-aligned lidar.
enum class AlignmentMode { None, SE3, Sim3, FourDof };

std::string alignmentLabel(AlignmentMode mode);  // "none (city frame; ...)", ...
AlignmentMode parseAlignmentMode(const std::string& name);  // none|se3|sim3|4dof; throws Error

// The similarity gt_T_est (scale s): an estimate pose P becomes (s R, t) * P with rotation R * R_P.
struct Alignment {
  SE3 transform = SE3::Identity();
  double scale = 1.0;
  std::vector<SE3> apply(const std::vector<SE3>& estimate) const;
};

// gt and estimate are associated pose pairs (same length, at least 1; 3 for SE3/Sim3).
Alignment alignTrajectories(const std::vector<SE3>& gt, const std::vector<SE3>& estimate, AlignmentMode mode);

}  // namespace hdprior
