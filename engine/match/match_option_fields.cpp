#include "engine/match/match_options.h"

namespace hdprior {

std::vector<OptionField> optionFields(MatchOptions& o) {
  return {
      {"backend", optionChoice(&o.backend, {"ndt2d", "pcl"}), "", "", "ndt2d: the 2-D NDT; pcl: PCL's 3-D NDT, the baseline"},
      {"cell_sizes", &o.cellSizes, "[0.5, 100]", "m", "NDT cell sizes, coarse to fine"},
      {"outlier_ratio", &o.outlierRatio, "(0, 1)", "", "NDT's outlier share in the score's mixture"},
      {"max_iterations", &o.maxIterations, "[1, 1000]", "", "Newton iterations per cell size"},
      {"time_budget_ms", &o.timeBudgetMs, "(0, 1000000]", "ms", "a match taking longer is rejected (eval turns this off)"},
      {"pcl_resolution", &o.pclResolution, "[0.5, 100]", "m", "voxel size of the pcl backend"},
      {"curb_huber", &o.curbHuber, "(0, 10]", "m", "robust loss of the curb refinement"},
      {"curb_max_distance", &o.curbMaxDistance, "(0, 100]", "m", "curb points farther than this from the drivable boundary are ignored"},
      {"min_curb_points", &o.minCurbPoints, "[1, 100000]", "", "curb points needed for the curb refinement and curb evidence"},
      {"boundary_band", &o.boundaryBand, "(0, 100]", "m", "points this close to the drivable boundary constrain its normal"},
      {"degenerate_ratio", &o.degenerateRatio, "[0, 1)", "", "a direction is observable when its boundary constraint is this share of the strongest ..."},
      {"min_boundary_points", &o.minBoundaryPoints, "[0, 1000000]", "", "... and at least this many point-equivalents"},
      {"min_information", &o.minInformation, "[0, 1000000000]", "1/m^2", "... and the NDT information there at least this"},
      {"min_points", &o.minPoints, "[1, 10000000]", "", "a match needs this many road points"},
      {"min_inlier_ratio", &o.minInlierRatio, "[0, 1]", "", "share of the road points that must land on the drivable area"},
      {"prediction_sigma", &o.predictionSigma, "(0, 1000]", "m, m, deg", "the odometry prediction's sigma (x, y, yaw) for the gate"},
      {"gate_chi2", &o.gateChi2, "(0, 1000000000]", "", "a match farther than this (chi-square, 3 dof) from the prediction is rejected; in a run it goes in only with re-anchoring"},
      {"stale_region_size", &o.staleRegionSize, "[0.5, 1000]", "m", "square regions in which a stale map is looked for"},
      {"stale_distance", &o.staleDistance, "(0, 1000]", "m", "points this far outside the drivable area at the prediction ..."},
      {"stale_distance_per_metre", &o.staleDistancePerMetre, "[0, 10]", "m/m", "... plus this per metre of range ..."},
      {"stale_share", &o.staleShare, "[0, 1]", "", "... for more than this share of a region's points: the region is left out"},
      {"evidence_share", &o.evidenceShare, "[0, 1)", "", "poses are allowed while at most this share of the points leave the drivable area ..."},
      {"evidence_min_points", &o.evidenceMinPoints, "[0, 1000000]", "", "... or this many"},
      {"evidence_margin", &o.evidenceMargin, "[-10, 10]", "m", "a point counts as off beyond this past the boundary"},
      {"evidence_curb_band", &o.evidenceCurbBand, "(0, 10]", "m", "curb points count as off this far from the boundary"},
      {"evidence_curb_share", &o.evidenceCurbShare, "[0, 1)", "", "share of the curb points that may leave"},
      {"evidence_stride", &o.evidenceStride, "[1, 1000]", "", "every n-th road point is counted (speed)"},
      {"evidence_max_offset", &o.evidenceMaxOffset, "(0, 100]", "m", "the evidence search's extent along and across the heading ..."},
      {"evidence_max_yaw_deg", &o.evidenceMaxYawDeg, "(0, 90]", "deg", "... and in yaw; beyond it a direction is unbounded"},
      {"evidence_kappa", &o.evidenceKappa, "(0, 100]", "", "a direction's sigma is the allowed half-width / kappa"},
      {"map_sigma", &o.mapSigma, "[0, 10]", "m", "the drivable polygon's own error"},
      {"map_sigma_yaw_deg", &o.mapSigmaYawDeg, "[0, 10]", "deg", "the same in yaw"},
      {"max_sigma_along", &o.maxSigmaAlong, "(0, 1000000]", "m", "a less certain along-track direction is reported unobservable"},
      {"max_sigma_lateral", &o.maxSigmaLateral, "(0, 1000000]", "m", "the same across the road"},
      {"max_sigma_yaw_deg", &o.maxSigmaYawDeg, "(0, 1000000]", "deg", "the same in yaw"}};
}

}  // namespace hdprior
