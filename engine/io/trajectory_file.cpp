#include "engine/io/trajectory_file.h"

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/kitti_trajectory.h"
#include "engine/io/text_lines.h"
#include "engine/io/tum_trajectory.h"

namespace hdprior {
namespace {

constexpr const char* kTimesOnlyForKitti = "a times file is only for KITTI poses (TUM lines carry their own timestamps)";

}  // namespace

const char* trajectoryFormatName(TrajectoryFormat format) { return format == TrajectoryFormat::Tum ? "tum" : "kitti"; }

TrajectoryFormat parseTrajectoryFormat(const std::string& name, const std::string& source) {
  if (name == "tum") return TrajectoryFormat::Tum;
  if (name == "kitti") return TrajectoryFormat::Kitti;
  throw Error(source, "must be tum or kitti, not '" + name + "'");
}

TrajectoryFormat detectTrajectoryFormat(const std::string& text, const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".tum") return TrajectoryFormat::Tum;
  if (extension == ".kitti") return TrajectoryFormat::Kitti;
  const std::vector<TextLine> lines = dataLines(text);
  if (lines.empty()) throw Error(path.string(), "no poses (only blank or comment lines)");
  const size_t fields = lines.front().fields.size();
  if (fields == 8) return TrajectoryFormat::Tum;
  if (fields == 12) return TrajectoryFormat::Kitti;
  throw Error(path.string() + ":" + std::to_string(lines.front().number),
              std::to_string(fields) + " fields: neither TUM (8) nor KITTI (12); give --odometry-format");
}

PoseTrajectory parseTrajectoryText(const std::string& text, TrajectoryFormat format, const std::string& source,
                                   const std::vector<int64_t>& sweepTimestampsNs, const std::optional<std::vector<int64_t>>& times,
                                   const std::string& timesSource) {
  if (format == TrajectoryFormat::Tum && times) throw Error(timesSource, kTimesOnlyForKitti);
  PoseTrajectory trajectory =
      format == TrajectoryFormat::Tum ? parseTum(text, source)
      : times ? kittiTrajectory(parseKitti(text, source), *times, source, "timestamps in " + timesSource)
              : kittiTrajectory(parseKitti(text, source), sweepTimestampsNs, source, "sweeps in the log");
  if (trajectory.size() < 2) {
    throw Error(source, std::to_string(trajectory.size()) + " pose" + (trajectory.size() == 1 ? "" : "s") +
                            ": at least 2 are needed to interpolate");
  }
  return trajectory;
}

TrajectoryFileContents readTrajectoryFile(const TrajectoryFileSpec& spec, const std::vector<int64_t>& sweepTimestampsNs) {
  const std::string text = readFileText(spec.file);
  const TrajectoryFormat format = spec.format ? *spec.format : detectTrajectoryFormat(text, spec.file);
  const std::string timesSource = spec.times ? spec.times->string() : "";
  if (format == TrajectoryFormat::Tum && spec.times) throw Error(timesSource, kTimesOnlyForKitti);
  std::optional<std::vector<int64_t>> times;
  if (spec.times) times = parseTimes(readFileText(*spec.times), timesSource);
  return {parseTrajectoryText(text, format, spec.file.string(), sweepTimestampsNs, times, timesSource), format};
}

}  // namespace hdprior
