#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/map/grid_geometry.h"

namespace hdprior {

// The physical shape of the ground at the edge of the road, as a scene family draws it (the
// map knows none of it): kerbs of varying height and shape with gaps, a gutter, the road's
// camber, sidewalks and the verge beyond, traffic islands the map paints over, and the kerb
// itself displaced from the map's drivable boundary (map error). Metres; "varying" values vary
// smoothly along the streets.
struct RoadsideOptions {
  double kerbHeightMin = 0.10, kerbHeightMax = 0.20;  // between them, varying
  double kerbWavelength = 80.0;     // metres over which the kerb height varies
  double noKerbFraction = 0.0;      // of the kerb length: verge without a kerb (height 0)
  double mountableFraction = 0.0;   // of the kerb length: a sloped (mountable) kerb
  double mountableWidth = 0.45;     // over which a sloped kerb rises
  double kerbCutSpacing = 0.0;      // mean metres of kerb between driveways / kerb cuts; 0: none
  double kerbCutLengthMin = 3.0, kerbCutLengthMax = 6.0;  // where the kerb ramps to 0
  double gutterWidth = 0.0, gutterDepth = 0.0;  // a dip just inside the kerb, deepest at it
  double camber = 0.0;              // road rises by camber * distance inside the kerb ...
  double camberCap = 3.0;           // ... up to this distance
  double sidewalkWidthMin = 4.0, sidewalkWidthMax = 4.0;  // between them, varying
  double sidewalkSlope = 0.0;       // cross slope, rising away from the road
  double terrainRelief = 0.0;       // amplitude of the small bumps of the grass beyond the sidewalk
  uint8_t roadReflectivity = 12, sidewalkReflectivity = 30, terrainReflectivity = 22;
  // The road's surface as the lidar's intensity sees it (0: clean asphalt and bright paint): paint
  // `paintContrast` times the road's reflectivity (yellow 0.8 of it) with a share `paintWear` of it
  // worn away (in 0.25 m cells), and bright asphalt `asphaltPatchGain` times the road's: patches
  // (sealed cracks, repairs, unmapped markings) on a share `asphaltPatchShare` of 0.25 m cells and
  // flecks (the aggregate) on a share `asphaltFleckShare` of 2 cm cells.
  double paintContrast = 0.0, paintWear = 0.0;
  double asphaltPatchShare = 0.0, asphaltFleckShare = 0.0, asphaltPatchGain = 2.5;
  double mapErrorAmplitude = 0.0;   // the kerb lies up to this far from the map's boundary ...
  double mapErrorWavelength = 50.0; // ... in a field varying over this many metres
};

// A raised, kerbed island inside the drivable area (physical only: the map paints over it):
// the points within `radius` of the segment a-b.
struct TrafficIsland {
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();
  double radius = 0.5;
  // Signed distance to the island's edge, positive inside.
  double inside(const Eigen::Vector2d& p) const;
};

// RoadsideOptions made concrete over an area: the varying fields sampled on a 0.5 m grid
// (bilinear between cell centres), and the height profile across the kerb.
class Roadside {
 public:
  // The fields at one point.
  struct Sample {
    float mapOffset = 0;     // physical kerb this far outwards of the map boundary
    float kerbHeight = 0;
    float kerbSlopeWidth = 0;  // 0: vertical kerb
    float sidewalkWidth = 0;
    float island = -1e3f;      // TrafficIsland::inside of the nearest island (clamped)
    float relief = 0;
  };

  // `kerbPoints`: samples of the map's drivable boundary (kerb cuts are placed among them).
  // Deterministic in `seed`.
  static Roadside build(const RoadsideOptions& options, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                        std::span<const Eigen::Vector2d> kerbPoints, std::span<const TrafficIsland> islands,
                        uint64_t seed);

  const RoadsideOptions& options() const { return options_; }
  const std::vector<TrafficIsland>& islands() const { return islands_; }
  const GridGeometry& grid() const { return grid_; }
  Sample at(const Eigen::Vector2d& city) const;  // clamped at the border
  // The map error field itself (not the grid), for tests.
  double mapErrorField(const Eigen::Vector2d& city) const;

  // Signed distance to the physical kerb (negative on the road) from the map's.
  static double physicalDistance(double mapDistance, const Sample& s) {
    return std::max(mapDistance - double(s.mapOffset), double(s.island));
  }
  // Height of the surface above the map's ground height at physical distance d.
  double rise(double d, const Sample& s) const;
  // Bounds of rise() over the area, and of its slope away from the kerb step and the gutter.
  double maxRise() const { return maxRise_; }
  double maxSlope() const { return maxSlope_; }
  double roadSlope() const { return 1.15 * options_.camber + 0.005; }  // on the road

 private:
  struct Wave {
    Eigen::Vector2d k = Eigen::Vector2d::Zero();
    double amplitude = 0.0, phase = 0.0;
  };
  static double sum(const std::vector<Wave>& waves, const Eigen::Vector2d& p);

  RoadsideOptions options_;
  std::vector<TrafficIsland> islands_;
  std::vector<Wave> mapError_;
  GridGeometry grid_;
  std::vector<Sample> cells_;
  double maxRise_ = 0.0, maxSlope_ = 0.0;
};

}  // namespace hdprior
