#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/io/lidar_sweep.h"
#include "engine/odom/odometry_options.h"

namespace hdprior {

enum class FeatureLabel : uint8_t { None, Flat, LessFlat };

// The LOAM plane features of one sweep, in the sweep's ego frame. flat is a subset of lessFlat
// (LOAM's nesting); lessFlat holds every non-rejected point whose curvature is below
// FeatureOptions::edgeCurvature.
struct FeatureCloud {
  std::vector<Eigen::Vector3f> flat, lessFlat;
};

// One ring's points in scan order, as the extractor sees them.
struct RingPoint {
  Eigen::Vector3f p;
  float azimuth = 0;  // radians
};

// Labels each point of one ring (in scan order) by curvature, after rejecting points near occlusion
// edges, points whose beam grazes the surface, out-of-range points and ring gaps: up to
// flatPerSector of each sector's flattest points below planeCurvature are Flat (the neighbours of
// each are suppressed), every other point below edgeCurvature is LessFlat.
std::vector<FeatureLabel> labelRing(const std::vector<RingPoint>& ring, const FeatureOptions& options);

// Splits a sweep into rings by laser_number, orders each ring by offset_ns (scan order; on the real
// Argoverse sweeps the file order within a ring is already monotone in offset_ns) and labels it.
FeatureCloud extractFeatures(const std::vector<Eigen::Vector3f>& points, const std::vector<LidarPoint>& raw,
                             const FeatureOptions& options, int threads = 1);

}  // namespace hdprior
