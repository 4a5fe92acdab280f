#pragma once
#include <filesystem>
#include <map>
#include <string>

#include "engine/geom/pose_trajectory.h"

namespace hdprior {

// city_SE3_egovehicle.feather: timestamp_ns, qw, qx, qy, qz, tx_m, ty_m, tz_m -> city_T_ego.
PoseTrajectory readEgoPoses(const std::filesystem::path& path);
void writeEgoPoses(const std::filesystem::path& path, const PoseTrajectory& cityTEgo);

// calibration/egovehicle_SE3_sensor.feather: sensor_name + the same pose columns -> ego_T_sensor.
using SensorCalibration = std::map<std::string, SE3>;
SensorCalibration readSensorCalibration(const std::filesystem::path& path);
void writeSensorCalibration(const std::filesystem::path& path, const SensorCalibration& egoTSensor);

}  // namespace hdprior
