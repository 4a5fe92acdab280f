#include "ui/odometry_file.h"

#include <utility>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"

namespace hdprior::ui {

OdometryFileOptions readingOptions(const OdometryFile& file) {
  OdometryFileOptions options;
  if (file.format == OdometryFile::Format::Tum) options.format = TrajectoryFormat::Tum;
  if (file.format == OdometryFile::Format::Kitti) options.format = TrajectoryFormat::Kitti;
  options.frame = file.frame;
  if (!file.times.empty()) options.times = std::filesystem::path(file.times);
  return options;
}

bool OdometryFile::open(const ArgoverseLog& log) {
  if (path.empty()) {
    close();
    failure_ = Error("odometry file", "none given");
    return false;
  }
  try {
    return open(givenOdometryOf(path, readingOptions(*this), log), log);
  } catch (const Error& e) {
    close();
    failure_ = e;
    return false;
  }
}

bool OdometryFile::open(GivenOdometry given, const ArgoverseLog& log) {
  close();
  try {
    city_ = givenOdometryInCity(given, log);
  } catch (const Error& e) {
    failure_ = e;
    return false;
  }
  path = given.file;
  format = given.format == TrajectoryFormat::Tum ? Format::Tum : Format::Kitti;
  frame = given.frame;
  given_ = std::move(given);
  return true;
}

void OdometryFile::close() {
  given_.reset();
  city_ = PoseTrajectory{};
  failure_.reset();
}

}  // namespace hdprior::ui
