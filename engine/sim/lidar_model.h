#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/geom/se3.h"
#include "engine/io/ego_poses.h"

namespace hdprior {

// One spinning 32-beam lidar of the stacked pair.
struct LidarUnit {
  std::string name;                 // up_lidar / down_lidar (the calibration's sensor_name)
  SE3 egoTSensor = SE3::Identity();
  std::vector<double> elevations;   // radians in the sensor frame, one per laser
  int firstLaserNumber = 0;         // laser_number of elevations[0]
  double startAzimuth = 0.0;        // ego-frame azimuth (radians) of the first firing
  // How the real sensor differs from what it believes (egoTSensor, the calibration written,
  // and elevations): none when empty / unset.
  std::vector<double> elevationErrors;  // radians the lasers really fire above `elevations`
  std::vector<double> rangeBiases;      // metres every range of a laser is too long
  std::optional<SE3> trueEgoTSensor;    // the mounting the rays really leave from
  bool ideal() const { return elevationErrors.empty() && rangeBiases.empty() && !trueEgoTSensor; }
};

// The sensor of an Argoverse 2 vehicle: two stacked 32-beam lidars spinning at 10 Hz in the
// same direction (clockwise from above, decreasing azimuth), half a turn apart; the down one
// mounted upside down. Firings are columns of all 32 lasers at once.
struct LidarModel {
  std::vector<LidarUnit> units;
  int azimuthSteps = 1800;           // columns per revolution
  int64_t periodNs = 100'000'000;    // one revolution = one sweep
  double maxRange = 200.0;
  double minRange = 1.0;

  // Time of column `c` after the sweep timestamp.
  int64_t columnOffsetNs(int c) const { return periodNs * c / azimuthSteps; }
  size_t beamCount() const;
  SensorCalibration calibration() const;  // sensor name -> ego_T_sensor (what the sensor believes)
};

// 64 beams at the non-uniform elevations of a 32-beam automotive lidar (-25..+15 degrees,
// dense near the horizon), placed like Argoverse 2's roof pair.
LidarModel argoverseLikeLidar();

}  // namespace hdprior
