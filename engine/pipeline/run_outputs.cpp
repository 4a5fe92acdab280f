#include "engine/pipeline/run_outputs.h"

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/io/file_bytes.h"
#include "engine/io/ply_writer.h"
#include "engine/io/tum_trajectory.h"
#include "engine/pipeline/keyframe_diagnostics.h"

namespace hdprior {
namespace {

using nlohmann::json;

json poseJson(const SE3& T) {
  const Eigen::Quaterniond q(T.rotation());
  return {{"t", {T.translation().x(), T.translation().y(), T.translation().z()}}, {"q_xyzw", {q.x(), q.y(), q.z(), q.w()}}};
}

json planarJson(const Eigen::Vector3d& p) { return {{"x", p.x()}, {"y", p.y()}, {"yaw_deg", p.z() * 180.0 / std::numbers::pi}}; }

json matrixJson(const Eigen::Matrix3d& m) {
  return {{m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}};
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
          {"ate_along_m", statsJson(e.ate.along)},
          {"ate_lateral_m", statsJson(e.ate.lateral)},
          {"rpe_10m", rpeJson(e.rpe10)}, {"rpe_100m", rpeJson(e.rpe100)}};
}

json sigmaJson(double sigma, double unit = 1.0) { return std::isfinite(sigma) ? json(sigma * unit) : json(nullptr); }

// A prior against the truth; an unobservable direction's sigma is null.
json priorErrorJson(const MatchErrorSample& s) {
  const double deg = 180.0 / std::numbers::pi;
  return {{"along_m", s.error(0)}, {"lateral_m", s.error(1)}, {"yaw_deg", s.error(2) * deg},
          {"sigma_along_m", sigmaJson(s.sigma(0))}, {"sigma_lateral_m", sigmaJson(s.sigma(1))},
          {"sigma_yaw_deg", sigmaJson(s.sigma(2), deg)}};
}

json directionJson(const DirectionCalibration& d, double unit = 1.0) {
  return {{"observed", d.observed}, {"rms", d.rms * unit}, {"share_beyond_3_sigma", d.beyond3Sigma},
          {"median_nees", d.medianNees}};
}

json calibrationJson(const MatchCalibration& c) {
  return {{"priors", c.matches}, {"along_m", directionJson(c.along)}, {"lateral_m", directionJson(c.lateral)},
          {"yaw_deg", directionJson(c.yaw, 180.0 / std::numbers::pi)}};
}

json constraintJson(const PriorConstraint& c) {
  return {{"category", c.category()}, {"along", c.along}, {"lateral", c.lateral}, {"yaw", c.yaw}};
}

json matchJson(const KeyframeMatch& k) {
  const MatchResult& r = k.match;
  const PriorConstraint c = constraintOf(k);
  return {{"status", toString(r.status)}, {"reason", r.reason}, {"constrains", c.label()}, {"constraint", constraintJson(c)},
          {"road_points", r.points}, {"curb_points", r.curbPoints}, {"stale_region_points", r.staleRegionPoints},
          {"initial", planarJson(r.initial)}, {"estimate", planarJson(r.estimate)},
          {"covariance_x_y_yaw", matrixJson(r.covariance)}, {"score", r.score}, {"score_per_point", r.scorePerPoint},
          {"inlier_ratio", r.inlierRatio}, {"gate_chi2", r.gateChi2}, {"observable_directions", r.observableDirections},
          {"evidence_half_widths", {{"along_m", sigmaJson(r.evidenceHalfWidths.x())},
                                    {"lateral_m", sigmaJson(r.evidenceHalfWidths.y())},
                                    {"yaw_deg", sigmaJson(r.evidenceHalfWidths.z(), 180.0 / std::numbers::pi)}}},
          {"laplace_sigmas", {{"along_m", sigmaJson(r.laplaceSigmas.x())},
                              {"lateral_m", sigmaJson(r.laplaceSigmas.y())},
                              {"yaw_deg", sigmaJson(r.laplaceSigmas.z(), 180.0 / std::numbers::pi)}}},
          {"iterations", r.iterations}, {"time_ms", r.timeMs}, {"prior", k.hasPrior}, {"innovation_chi2", k.innovationChi2},
          {"gated", k.gated}, {"gate_quantile", k.gateQuantile}};
}

json diagnosticsJson(const KeyframeDiagnostic& d) {
  json out = json::object();
  for (size_t f = 0; f < kDiagnosticFields; ++f) out[diagnosticKey(DiagnosticField(f))] = sigmaJson(d.values[f]);
  return out;
}

json keyframesJson(const PipelineRun& run) {
  json keyframes = json::array();
  const std::vector<KeyframeDiagnostic> diagnostics = keyframeDiagnostics(
      run.matches, run.optimizedKeyframes, run.groundTruth, [&](size_t f) { return run.sweepOfFrame(f); });
  for (size_t k = 0; k < run.odometry->keyframes().size(); ++k) {
    const Keyframe& kf = run.odometry->keyframes()[k];
    std::vector<double> cov(kf.relativeCovariance.data(), kf.relativeCovariance.data() + 36);
    // Frames as the log numbers its sweeps (after a skipped sweep, not the odometry's frame count).
    std::vector<size_t> submapSweeps;
    for (size_t f : kf.submapFrames) submapSweeps.push_back(run.sweepOfFrame(f));
    json j = {{"index", k}, {"frame", run.sweepOfFrame(kf.frame)}, {"timestamp_ns", kf.timestampNs},
              {"city_T_ego", poseJson(run.cityTOdom * kf.odomTEgo)}, {"previous_T_this", poseJson(kf.previousTThis)},
              {"relative_covariance_v_w", cov}, {"submap_frames", submapSweeps}};
    if (k < run.optimizedKeyframes.size()) j["optimized_city_T_ego"] = poseJson(run.optimizedKeyframes[k]);
    if (k < run.matches.size()) j["match"] = matchJson(run.matches[k]);
    if (k < diagnostics.size()) j["diagnostics"] = diagnosticsJson(diagnostics[k]);
    if (k < run.matches.size() && run.groundTruth.covers(kf.timestampNs)) {
      const Eigen::Vector3d e = planarError(planarPose(run.groundTruth.at(kf.timestampNs)), run.matches[k].match.estimate);
      j["match_error"] = {{"along_m", e.x()}, {"lateral_m", e.y()}, {"yaw_deg", e.z() * 180.0 / std::numbers::pi}};
    }
    if (k < run.matches.size() && run.matches[k].hasPrior && run.groundTruth.covers(kf.timestampNs)) {
      const KeyframeMatch& m = run.matches[k];
      j["prior_error"] = priorErrorJson(matchErrorSample(planarPose(run.groundTruth.at(kf.timestampNs)),
                                                         planarPose(m.prior.pose), marginalPlanarInformation(m.prior)));
    }
    keyframes.push_back(j);
  }
  return keyframes;
}

json timingJson(const StageTimes& t, size_t sweeps) {
  return {{"odometry_s", t.odometryS}, {"road_points_s", t.roadPointsS}, {"match_s", t.matchS}, {"graph_s", t.graphS},
          {"pipeline_s", t.pipelineS}, {"sweeps_per_s", t.pipelineS > 0 ? double(sweeps) / t.pipelineS : 0.0},
          {"global_map_s", t.mapS}};
}

// The drift injected into the odometry's poses (all zero: none).
json driftJson(const OdometryDrift& d) {
  return {{"scale", d.scale}, {"yaw_deg_per_100m", d.yawDegPer100m}, {"pitch_deg_per_100m", d.pitchDegPer100m}};
}

// The graph's odometry drift model as the run used it.
// The drift model in use and, when it was estimated, every candidate's log-likelihood: a pick that
// won by a fraction of a nat is noise, and the user should see that.
json driftModelJson(const PoseGraphOptions& g, const std::vector<DriftModelLikelihood::Candidate>& candidates) {
  json out = {{"translation_sigma_per_m", g.odometryTranslationSigmaPerM},
              {"rotation_sigma_deg_per_m", g.odometryRotationSigmaDegPerM}, {"margin_nats", g.driftModelMarginNats},
              {"map_error_length_m", g.mapErrorLength}};
  if (!candidates.empty()) {
    json list = json::array();
    for (const auto& c : candidates) {
      list.push_back({{"factor", c.factor}, {"map_error_length_m", c.mapErrorLength}, {"log_likelihood", c.logLikelihood},
                      {"chosen", c.chosen}});
    }
    out["candidates"] = list;
  }
  return out;
}

// Where the odometry's poses came from: the built-in lidar odometry or a trajectory file.
json odometrySourceJson(const PipelineRun& run) {
  if (!run.givenOdometry) return {{"kind", "lidar"}};
  const GivenOdometry& g = *run.givenOdometry;
  return {{"kind", "file"}, {"file", g.file}, {"format", trajectoryFormatName(g.format)}, {"frame", givenOdometryFrameName(g.frame)},
          {"poses", g.trajectory.size()}};
}

// The sweeps the run could not read and left out.
json skippedJson(const std::vector<SkippedSweep>& skipped) {
  json files = json::array();
  for (const SkippedSweep& s : skipped) files.push_back(s.file.filename().string());
  return {{"count", skipped.size()}, {"files", files}};
}

json metricsJson(const ArgoverseLog& log, const PipelineRun& run, const RunMetrics& metrics) {
  json aligned = json::array();
  for (const auto& e : metrics.odometryAligned) aligned.push_back(evaluationJson(e));
  json m = {{"log", log.id()},
            {"priors", run.hasPriors()},
            {"sweeps", run.estimate.size()},
            {"skipped_sweeps", skippedJson(run.skippedSweeps)},
            {"keyframes", run.odometry->keyframes().size()},
            {"timing", timingJson(run.times, run.estimate.size())},
            {"max_local_map_points", run.maxLocalMapPoints},
            {"map_points", run.mapPoints.size()},
            {"odometry_source", odometrySourceJson(run)},
            {"odometry_drift", driftJson(run.odometryDrift)},
            {"odometry", evaluationJson(metrics.odometry)},
            {"odometry_aligned", aligned}};
  if (metrics.optimized) {
    m["optimized"] = evaluationJson(*metrics.optimized);
    m["matches"] = {{"accepted", metrics.matches.accepted}, {"degenerate", metrics.matches.degenerate},
                    {"rejected", metrics.matches.rejected}, {"constraints", json::object()},
                    {"summary", constraintSummary(metrics.matches.constraints)}};
    for (const auto& [category, n] : countConstraints(metrics.matches.constraints)) m["matches"]["constraints"][category] = n;
    m["odometry_drift_model"] = driftModelJson(run.graphOptions, run.driftModelCandidates);
    m["prior_calibration"] = calibrationJson(metrics.priorCalibration);
    m["final_solve"] = {{"iterations", run.finalSolve.iterations}, {"initial_cost", run.finalSolve.initialCost},
                        {"final_cost", run.finalSolve.finalCost}, {"converged", run.finalSolve.converged}};
  }
  return m;
}

}  // namespace

void writeRunOutputs(const std::filesystem::path& dir, const ArgoverseLog& log, const PipelineRun& run,
                     const RunMetrics& metrics) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir)) throw Error(dir.string(), "cannot create the output folder");
  writeTum(dir / "groundtruth.tum", run.groundTruth);
  writeTum(dir / "odometry.tum", run.estimate);
  if (run.hasPriors()) writeTum(dir / "optimized.tum", run.optimized);
  writeFileAtomically(dir / "keyframes.json", keyframesJson(run).dump(1) + "\n");
  writeFileAtomically(dir / "metrics.json", metricsJson(log, run, metrics).dump(2) + "\n");
  writePly(dir / "map.ply", run.mapPoints, run.mapIntensity);
}

}  // namespace hdprior
