#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/geom/pose_trajectory.h"

namespace hdprior {

enum class TrajectoryFormat { Tum, Kitti };

const char* trajectoryFormatName(TrajectoryFormat format);  // "tum", "kitti"
// "tum" or "kitti"; anything else throws Error(source, ...).
TrajectoryFormat parseTrajectoryFormat(const std::string& name, const std::string& source);

// A file's format when none is given: by extension (.tum: TUM; .kitti: KITTI); otherwise (.txt is
// used by both) by the number of fields of the first data line: 8 TUM, 12 KITTI. Throws Error
// naming the file (and the line) when neither fits.
TrajectoryFormat detectTrajectoryFormat(const std::string& text, const std::filesystem::path& path);

// A trajectory file as given on the command line: the file, its format (nullopt: detected) and, for
// KITTI, an optional times file (one timestamp per line, seconds on the log's clock).
struct TrajectoryFileSpec {
  std::filesystem::path file;
  std::optional<TrajectoryFormat> format;
  std::optional<std::filesystem::path> times;
};

// The file's poses with their timestamps: TUM's own, or for KITTI the times file's or, without one,
// `sweepTimestampsNs` (one line per sweep, in order). Throws Error naming the file and the line for a
// bad line, the file alone for fewer than 2 poses or a KITTI line count that differs from the sweeps
// (or the times), and the times file for one given with TUM.
PoseTrajectory parseTrajectoryText(const std::string& text, TrajectoryFormat format, const std::string& source,
                                   const std::vector<int64_t>& sweepTimestampsNs,
                                   const std::optional<std::vector<int64_t>>& times = std::nullopt,
                                   const std::string& timesSource = "");
struct TrajectoryFileContents {
  PoseTrajectory trajectory;
  TrajectoryFormat format = TrajectoryFormat::Tum;  // as given or detected
};
TrajectoryFileContents readTrajectoryFile(const TrajectoryFileSpec& spec, const std::vector<int64_t>& sweepTimestampsNs);

}  // namespace hdprior
