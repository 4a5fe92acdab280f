#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/option_fields.h"

namespace hdprior {

// Concentric-zone ground segmentation (after Patchwork, Lim et al. 2021): the plane around
// the vehicle is cut into zones of rings x sectors whose bins grow with range; in each bin
// a plane is fitted to the lowest points (seeds) and refined a few times, and accepted as
// ground when it is near-horizontal and not far above the expected ground level.
// Points are in the ego (or key-frame) frame: x forward, y left, z up.
struct GroundSegmentationOptions {
  double groundZ = -0.32;   // ground level under the ego origin (Argoverse: about -0.32 m)
  double minRange = 2.7;    // closer returns hit the vehicle itself
  double maxRange = 60.0;
  // Zone outer radii (metres) after minRange, with radial rings and azimuth sectors per zone.
  std::vector<double> zoneRadii = {8.0, 16.0, 30.0, 60.0};
  std::vector<int> zoneRings = {5, 4, 4, 3};
  std::vector<int> zoneSectors = {32, 64, 72, 48};
  int minBinPoints = 6;
  int seedPoints = 10;             // lowest points averaged to the lowest-point representative
  double seedHeight = 0.20;        // seeds: up to this far above that representative
  double planeDistance = 0.10;     // ground: this close to the bin's plane
  int iterations = 3;              // plane refits
  double maxTiltDeg = 20.0;        // steeper planes are walls, cars, vegetation
  double maxElevation = 0.6;       // the plane at the bin centre may lie this far above groundZ
  double elevationPerMetre = 0.05; // ... plus this much per metre of range (slopes)
};
std::vector<OptionField> optionFields(GroundSegmentationOptions& o);  // its configuration keys


// One flag per point: 1 = ground.
std::vector<uint8_t> segmentGround(std::span<const Eigen::Vector3d> points, const GroundSegmentationOptions& options = {});

}  // namespace hdprior
