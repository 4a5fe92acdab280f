#include "engine/pipeline/odometry_run.h"

#include <chrono>
#include <cmath>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/ply_writer.h"
#include "engine/io/tum_trajectory.h"
#include "engine/odom/voxel_feature_map.h"

namespace hdprior {
namespace {

using nlohmann::json;

json poseJson(const SE3& T) {
  const Eigen::Quaterniond q(T.rotation());
  return {{"t", {T.translation().x(), T.translation().y(), T.translation().z()}}, {"q_xyzw", {q.x(), q.y(), q.z(), q.w()}}};
}

json statsJson(const ErrorStats& s) {
  return {{"count", s.count}, {"mean", s.mean}, {"median", s.median}, {"rmse", s.rmse}, {"std", s.std}, {"max", s.max}};
}

json rpeJson(const RpeResult& r) {
  if (r.segments == 0) return {{"segment_m", r.length}, {"segments", 0}, {"note", "trajectory shorter than the segment"}};
  return {{"segment_m", r.length}, {"segments", r.segments}, {"translation_percent", r.translationPercent},
          {"yaw_deg_per_100m", r.yawDegPer100m}, {"rotation_deg_per_100m", r.rotationDegPer100m}};
}

json evaluationJson(const TrajectoryEvaluation& e) {
  return {{"alignment", e.label}, {"scale", e.scale}, {"path_length_m", e.pathLength},
          {"ate_translation_m", statsJson(e.ate.translation)}, {"ate_rotation_deg", statsJson(e.ate.rotationDeg)},
          {"rpe_10m", rpeJson(e.rpe10)}, {"rpe_100m", rpeJson(e.rpe100)}};
}

}  // namespace

OdometryRun runOdometry(const ArgoverseLog& log, const Config& config, const std::function<void(size_t, size_t)>& progress,
                        double mapVoxel) {
  const size_t n = log.sweepCount();
  if (n == 0) throw Error((log.dir() / "sensors" / "lidar").string(), "the log has no sweeps");
  const auto& stamps = log.sweepTimestamps();
  if (!log.cityTEgo().covers(stamps.front())) {
    throw Error(log.dir().string(), "the ground-truth poses do not cover the first sweep (needed to anchor the start)");
  }
  OdometryRun run;
  run.odometry = std::make_unique<Odometry>(config.odometry, config.keyframes);
  run.cityTOdom = log.cityTEgo().at(stamps.front());
  std::unordered_set<VoxelKey, VoxelKeyHash> occupied;
  std::vector<int64_t> estimateStamps, gtStamps;
  std::vector<SE3> estimatePoses, gtPoses;
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < n; ++i) {
    const auto sweep = log.sweep(i);
    if (sweep->points.empty()) throw Error(log.sweepPath(i).string(), "the sweep has zero points");
    const OdometryFrame& frame = run.odometry->registerSweep(*sweep);
    const SE3 cityTEgo = run.cityTOdom * frame.odomTEgo;
    estimateStamps.push_back(stamps[i]);
    estimatePoses.push_back(cityTEgo);
    if (log.cityTEgo().covers(stamps[i])) {
      gtStamps.push_back(stamps[i]);
      gtPoses.push_back(log.cityTEgo().at(stamps[i]));
    }
    // The map is built from the keyframes' sweeps: same coverage at a fraction of the cost.
    const bool isKeyframe = run.odometry->keyframes().back().frame == i;
    const Eigen::Isometry3f T = cityTEgo.cast<float>();
    const auto points = isKeyframe ? run.odometry->deskewed(*sweep, i) : std::vector<Eigen::Vector3f>{};
    for (size_t j = 0; j < points.size(); ++j) {
      const Eigen::Vector3f p = T * points[j];
      if (occupied.insert(voxelOf(p, float(mapVoxel))).second) {
        run.mapPoints.push_back(p);
        run.mapIntensity.push_back(float(sweep->points[j].intensity));
      }
    }
    run.maxLocalMapPoints = std::max(run.maxLocalMapPoints, run.odometry->localMapPoints());
    if (progress) progress(i + 1, n);
  }
  run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.estimate = PoseTrajectory(estimateStamps, estimatePoses, "odometry");
  run.groundTruth = PoseTrajectory(gtStamps, gtPoses, (log.dir() / "city_SE3_egovehicle.feather").string());
  return run;
}

RunMetrics evaluateRun(const OdometryRun& run) {
  RunMetrics m;
  m.anchored = evaluateTrajectory(run.groundTruth, run.estimate, AlignmentMode::None);
  if (run.estimate.size() >= 3) {
    for (AlignmentMode mode : {AlignmentMode::SE3, AlignmentMode::Sim3, AlignmentMode::FourDof}) {
      m.aligned.push_back(evaluateTrajectory(run.groundTruth, run.estimate, mode));
    }
  }
  return m;
}

void writeRunOutputs(const std::filesystem::path& dir, const ArgoverseLog& log, const OdometryRun& run,
                     const RunMetrics& metrics) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir)) throw Error(dir.string(), "cannot create the output folder");

  json keyframes = json::array();
  for (size_t k = 0; k < run.odometry->keyframes().size(); ++k) {
    const Keyframe& kf = run.odometry->keyframes()[k];
    std::vector<double> cov(kf.relativeCovariance.data(), kf.relativeCovariance.data() + 36);
    keyframes.push_back({{"index", k}, {"frame", kf.frame}, {"timestamp_ns", kf.timestampNs},
                         {"city_T_ego", poseJson(run.cityTOdom * kf.odomTEgo)},
                         {"previous_T_this", poseJson(kf.previousTThis)},
                         {"relative_covariance_v_w", cov},
                         {"submap_frames", kf.submapFrames}});
  }
  json aligned = json::array();
  for (const auto& e : metrics.aligned) aligned.push_back(evaluationJson(e));
  const size_t sweeps = run.estimate.size();
  const json metricsJson = {
      {"log", log.id()},
      {"priors", "none (--no-prior)"},
      {"sweeps", sweeps},
      {"keyframes", run.odometry->keyframes().size()},
      {"wall_time_s", run.wallSeconds},
      {"sweeps_per_s", run.wallSeconds > 0 ? double(sweeps) / run.wallSeconds : 0.0},
      {"max_local_map_points", run.maxLocalMapPoints},
      {"map_points", run.mapPoints.size()},
      {"odometry", evaluationJson(metrics.anchored)},
      {"odometry_aligned", aligned}};

  writeTum(dir / "groundtruth.tum", run.groundTruth);
  writeTum(dir / "odometry.tum", run.estimate);
  writeFileAtomically(dir / "keyframes.json", keyframes.dump(1) + "\n");
  writeFileAtomically(dir / "metrics.json", metricsJson.dump(2) + "\n");
  writePly(dir / "map.ply", run.mapPoints, run.mapIntensity);
}

}  // namespace hdprior
