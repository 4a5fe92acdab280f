#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "engine/error.h"
#include "engine/geom/pose_trajectory.h"
#include "engine/odom/given_odometry.h"

namespace hdprior {
class ArgoverseLog;
}

namespace hdprior::ui {

// A trajectory file opened in the app as the odometry (the Pipeline tab's fields, `view --odometry`,
// a script's `odometry`), read and checked against the log by the engine path `run --odometry`
// takes (givenOdometryOf, givenOdometryInCity): a bad file is one line naming the file and the line.
class OdometryFile {
 public:
  // What the Pipeline tab edits: the file, its format (auto: detected), its frame, a KITTI times file.
  enum class Format { Auto, Tum, Kitti };
  std::string path, times;
  Format format = Format::Auto;
  GivenOdometryFrame frame = GivenOdometryFrame::First;
  bool use = true;  // the next run takes the file as its odometry; false: the built-in odometry

  // Reads `path` with the fields above. On success the file is open; on failure none is and
  // error() says why.
  bool open(const ArgoverseLog& log);
  // A file already read (view --odometry): checks that it covers the log's sweeps.
  bool open(GivenOdometry given, const ArgoverseLog& log);
  void close();

  bool isOpen() const { return given_.has_value(); }
  const std::optional<GivenOdometry>& given() const { return given_; }
  // The file's poses at every sweep in the city frame, as a run over it anchors them.
  const PoseTrajectory& cityTrajectory() const { return city_; }
  // Why the last open failed (one line naming the file and the line); empty when it did not.
  std::string error() const { return failure_ ? failure_->what() : ""; }
  const std::optional<Error>& failure() const { return failure_; }
  // The given odometry a run takes: the open file when `use`, else none (the built-in odometry).
  std::optional<GivenOdometry> forRun() const { return use ? given_ : std::nullopt; }

 private:
  std::optional<GivenOdometry> given_;
  PoseTrajectory city_;
  std::optional<Error> failure_;
};

// The engine's reading options for the fields (the same as run's --odometry-format/-frame/-times).
OdometryFileOptions readingOptions(const OdometryFile& file);

}  // namespace hdprior::ui
