#include "engine/odom/odometry_options.h"

namespace hdprior {

std::vector<OptionField> optionFields(FeatureOptions& o) {
  return {
      {"sectors", &o.sectors, "[1, 64]", "", "sectors per laser ring; each picks its own plane features"},
      {"flat_per_sector", &o.flatPerSector, "[1, 1000]", "", "plane features picked per sector, the flattest first"},
      {"plane_curvature", &o.planeCurvature, "(0, 1]", "", "LOAM curvature below which a point may be a plane feature"},
      {"min_range", &o.minRange, "[0, 1000]", "m", "nearer returns (the vehicle itself) are not features"},
      {"max_range", &o.maxRange, "(0, 10000]", "m", "farther returns are not features"}};
}

std::vector<OptionField> optionFields(DeskewOptions& o) {
  return {
      {"mode", optionChoice(&o.mode, {"none", "constant_velocity"}), "", "",
       "none: sweeps are stored motion-compensated (Argoverse 2); constant_velocity: deskew raw sweeps by offset_ns"}};
}

std::vector<OptionField> optionFields(RegistrationOptions& o) {
  return {
      {"outer_iterations", &o.outerIterations, "[1, 100]", "", "re-association rounds of scan-to-map registration"},
      {"max_outer_iterations", &o.maxOuterIterations, "[1, 100]", "",
       "rounds at most: past outer_iterations, rounds go on while one still moves the pose 1 cm or 0.05 deg"},
      {"solver_iterations", &o.solverIterations, "[1, 1000]", "", "Ceres iterations per round"},
      {"huber_scale", &o.huberScale, "(0, 100]", "m", "robust loss scale of the point-to-plane residuals"},
      {"max_correspondence", &o.maxCorrespondence, "(0, 10]", "m", "nearest-neighbour gate of a correspondence"},
      {"plane_downsample", &o.planeDownsample, "(0, 100]", "m", "voxel size of the scan's plane queries"},
      {"threads", &o.threads, "[1, 64]", "", "threads of the correspondence search and feature extraction"}};
}

std::vector<OptionField> optionFields(LocalMapOptions& o) {
  return {
      {"voxel_size", &o.voxelSize, "[0.1, 100]", "m", "voxel size of the local map's hash"},
      {"max_points_per_voxel", &o.maxPointsPerVoxel, "[1, 10000]", "", "points kept per voxel"},
      {"min_point_spacing", &o.minPointSpacing, "[0, 100]", "m", "a new point this close to one in its voxel is dropped"},
      {"radius", &o.radius, "[1, 100000]", "m", "voxels farther than this from the vehicle are removed"}};
}

std::vector<OptionField> optionFields(KeyframeOptions& o) {
  return {
      {"distance", &o.distance, "[0, 100000]", "m", "a keyframe after this distance travelled ..."},
      {"rotation_deg", &o.rotationDeg, "[0, 360]", "deg", "... or this much turned"}};
}

}  // namespace hdprior
