#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/option_checks.h"
#include "engine/error.h"
#include "engine/eval/match_calibration.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/prior_constraint.h"

namespace hdprior::app {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// "dx,dy,dyaw_deg" -> (dx, dy, dyaw in radians).
Eigen::Vector3d parseOffset(const std::string& text) {
  Eigen::Vector3d v;
  std::istringstream in(text);
  char c1 = 0, c2 = 0;
  if (!(in >> v.x() >> c1 >> v.y() >> c2 >> v.z()) || c1 != ',' || c2 != ',' || !in.eof() || !v.allFinite() ||
      v.head<2>().norm() > 100.0 || std::abs(v.z()) > 180.0) {
    throw Error("option --init", "'" + text + "' is not dx,dy,dyaw_deg (metres, metres, degrees; |d| <= 100 m)");
  }
  v.z() *= kDeg;
  return v;
}

MatchBackend parseBackend(const std::string& text) {
  if (text == "ndt2d") return MatchBackend::Ndt2d;
  if (text == "pcl") return MatchBackend::PclNdt;
  throw Error("option --backend", "'" + text + "' is not ndt2d or pcl");
}

std::string pose(const Eigen::Vector3d& p) {
  char b[160];
  std::snprintf(b, sizeof b, "{\"x\": %.4f, \"y\": %.4f, \"yaw_deg\": %.4f}", p.x(), p.y(), p.z() / kDeg);
  return b;
}

std::string matrix(const Eigen::Matrix3d& m) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r) {
    char b[160];
    std::snprintf(b, sizeof b, "%s[%.6g, %.6g, %.6g]", r ? ", " : "", m(r, 0), m(r, 1), m(r, 2));
    s += b;
  }
  return s + "]";
}

// A number, or null where it is infinite (JSON has no infinity): an unobservable direction.
std::string finiteOrNull(double v) {
  if (!std::isfinite(v)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.4f", v);
  return b;
}

struct MatchArguments {
  std::string log, init = "0,0,0", backend;
  long long frame = 0;
  double timeBudgetMs = MatchOptions{}.timeBudgetMs;
  bool timeBudgetGiven = false;
  ConfigArguments config;
};

int runMatch(const MatchArguments& a) {
  const long long frame = a.frame;
  const Eigen::Vector3d offset = parseOffset(a.init);
  const Config config = configOf(a.config);
  MatchOptions options = config.match;
  if (!a.backend.empty()) options.backend = parseBackend(a.backend);
  if (a.timeBudgetGiven) options.timeBudgetMs = a.timeBudgetMs;
  if (!(options.timeBudgetMs > 0)) throw Error("option --time-budget", "must be a positive number of milliseconds");

  const ArgoverseLog log(a.log);
  if (size_t(frame) >= log.sweepCount()) {
    throw Error("option --frame", "frame " + std::to_string(frame) + " is out of range (the log has " +
                                      std::to_string(log.sweepCount()) + " sweeps)");
  }
  const int64_t stamp = log.sweepTimestamps()[size_t(frame)];
  if (!log.cityTEgo().covers(stamp)) throw Error(log.dir().string(), "no ground-truth pose at the sweep's timestamp");
  HdMapOptions mapOptions;
  mapOptions.ndtCellSizes = options.cellSizes;
  const HdMap map = HdMap::load(log.mapFiles(), mapOptions);

  // Roll and pitch come from the ground truth here (the pipeline takes them from odometry).
  const SE3 truth3 = log.cityTEgo().at(stamp);
  const Eigen::Vector3d truth = planarPose(truth3);
  const auto sweep = log.sweep(size_t(frame));
  const PlanarRoadPoints points = sweepRoadPoints(*sweep, levelRotation(truth3), config.roadPoints);
  const Eigen::Vector3d initial = offsetPose(truth, offset);
  MapMatcher matcher(map, options);
  const MatchResult r = matcher.match(points.road, initial, points.curb);
  const Eigen::Vector3d e = planarError(truth, r.estimate);

  std::printf("{\n  \"log\": \"%s\",\n  \"frame\": %lld,\n  \"timestamp_ns\": %lld,\n  \"backend\": \"%s\",\n",
              log.id().c_str(), frame, (long long)stamp, options.backend == MatchBackend::Ndt2d ? "ndt2d" : "pcl");
  std::printf("  \"curb_points\": %zu,\n", points.curb.size());
  std::printf("  \"road_points\": %zu,\n  \"truth\": %s,\n  \"initial\": %s,\n  \"estimate\": %s,\n", r.points,
              pose(truth).c_str(), pose(initial).c_str(), pose(r.estimate).c_str());
  std::printf("  \"error\": {\"along\": %.4f, \"lateral\": %.4f, \"yaw_deg\": %.4f},\n", e.x(), e.y(), e.z() / kDeg);
  std::printf("  \"status\": \"%s\",\n  \"reason\": \"%s\",\n", toString(r.status), r.reason.c_str());
  std::printf("  \"constrains\": \"%s\",\n", constraintOf(r).label().c_str());
  std::printf("  \"score\": %.4f,\n  \"score_per_point\": %.5f,\n  \"inlier_ratio\": %.4f,\n  \"gate_chi2\": %.4f,\n",
              r.score, r.scorePerPoint, r.inlierRatio, r.gateChi2);
  std::printf("  \"iterations\": %d,\n  \"time_ms\": %.3f,\n  \"observable_directions\": %d,\n", r.iterations,
              r.timeMs, r.observableDirections);
  const Eigen::Vector3d sigma = matchErrorSample(truth, r.estimate, r.information).sigma;
  std::printf("  \"sigma\": {\"along\": %s, \"lateral\": %s, \"yaw_deg\": %s},\n", finiteOrNull(sigma.x()).c_str(),
              finiteOrNull(sigma.y()).c_str(), finiteOrNull(sigma.z() / kDeg).c_str());
  const Eigen::Vector3d& w = r.evidenceHalfWidths;
  std::printf("  \"evidence_half_widths\": {\"along\": %s, \"lateral\": %s, \"yaw_deg\": %s},\n",
              finiteOrNull(w.x()).c_str(), finiteOrNull(w.y()).c_str(), finiteOrNull(w.z() / kDeg).c_str());
  std::printf("  \"covariance_x_y_yaw\": %s,\n  \"information_x_y_yaw\": %s\n}\n", matrix(r.covariance).c_str(),
              matrix(r.information).c_str());
  return 0;
}

}  // namespace

Command addMatchCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "match", "match sweep N's road points to the drivable area from the ground-truth pose moved by an offset; prints JSON");
  auto a = std::make_shared<MatchArguments>();
  addLogArgument(*command, a->log);
  command->add_option("--frame", a->frame, "the sweep to match")->type_name("N")->default_str("")->required()->check(integerAtLeast(0));
  command->add_option("--init", a->init, "the start: the ground-truth pose moved dx forward, dy left (metres) and dyaw degrees")
      ->type_name("dx,dy,dyaw_deg")
      ->check(parsedBy([](const std::string& text) { parseOffset(text); }));
  command->add_option("--backend", a->backend, "the matcher (default: the configuration's match.backend)")->type_name("ndt2d|pcl")->check(parsedBy([](const std::string& text) {
    parseBackend(text);
  }));
  CLI::Option* budget = command->add_option("--time-budget", a->timeBudgetMs, "the matcher's wall-clock budget (default: the configuration's match.time_budget_ms)")
                            ->type_name("MS")
                            ->default_str("")
                            ->check(finiteNumber());
  addConfigOption(*command, a->config);
  command->callback([a, budget] { a->timeBudgetGiven = budget->count() > 0; });
  return {command, [a] { return runMatch(*a); }};
}

}  // namespace hdprior::app
