#include "engine/eval/log_evaluation_file.h"

#include <limits>

#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"

namespace hdprior {
namespace {

using nlohmann::json;

// JSON has no infinity or NaN: nlohmann writes them as null (an unobservable direction's sigma is
// +infinity), which Reader reads back as the field's `nonFinite`.

json statsJson(const ErrorStats& s) {
  return {{"count", s.count}, {"mean", s.mean}, {"median", s.median}, {"rmse", s.rmse},
          {"std", s.std}, {"max", s.max}};
}

json rpeJson(const RpeResult& r) {
  return {{"length_m", r.length}, {"segments", r.segments}, {"translation_percent", r.translationPercent},
          {"yaw_deg_per_100m", r.yawDegPer100m}, {"rotation_deg_per_100m", r.rotationDegPer100m}};
}

json trajectoryJson(const TrajectoryEvaluation& e) {
  return {{"label", e.label},
          {"scale", e.scale},
          {"path_length_m", e.pathLength},
          {"ate_translation_m", statsJson(e.ate.translation)},
          {"ate_rotation_deg", statsJson(e.ate.rotationDeg)},
          {"ate_along_m", statsJson(e.ate.along)},
          {"ate_lateral_m", statsJson(e.ate.lateral)},
          {"rpe_10m", rpeJson(e.rpe10)},
          {"rpe_100m", rpeJson(e.rpe100)}};
}

json priorErrorJson(const MatchErrorSample& s) {
  return {{"error", {s.error(0), s.error(1), s.error(2)}},
          {"sigma", {s.sigma(0), s.sigma(1), s.sigma(2)}}};
}

// Reading: every field is required; `where` names it in the error.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  const json& member(const json& obj, const char* key, const std::string& where) const {
    return json_reading::member(obj, key, where, file_);
  }
  double number(const json& obj, const char* key, const std::string& where,
                double nonFinite = std::numeric_limits<double>::quiet_NaN()) const {
    const json& v = member(obj, key, where);
    return v.is_null() ? nonFinite : json_reading::number(v, where + "." + key, file_);
  }
  size_t count(const json& obj, const char* key, const std::string& where) const {
    const int64_t n = json_reading::integer(member(obj, key, where), where + "." + key, file_);
    if (n < 0) throw Error(file_, where + "." + key + " is negative");
    return size_t(n);
  }
  std::string text(const json& obj, const char* key, const std::string& where) const {
    const json& v = member(obj, key, where);
    if (!v.is_string()) throw Error(file_, where + "." + key + " is not a string");
    return v.get<std::string>();
  }
  const json& array(const json& obj, const char* key, const std::string& where) const {
    const json& v = member(obj, key, where);
    if (!v.is_array()) throw Error(file_, where + "." + key + " is not an array");
    return v;
  }

  ErrorStats stats(const json& obj, const char* key, const std::string& where) const {
    const json& s = member(obj, key, where);
    const std::string w = where + "." + key;
    return {count(s, "count", w), number(s, "mean", w), number(s, "median", w), number(s, "rmse", w), number(s, "std", w),
            number(s, "max", w)};
  }

  RpeResult rpe(const json& obj, const char* key, const std::string& where) const {
    const json& r = member(obj, key, where);
    const std::string w = where + "." + key;
    return {number(r, "length_m", w), count(r, "segments", w), number(r, "translation_percent", w),
            number(r, "yaw_deg_per_100m", w), number(r, "rotation_deg_per_100m", w)};
  }

  TrajectoryEvaluation trajectory(const json& t, const std::string& where) const {
    TrajectoryEvaluation e;
    e.label = text(t, "label", where);
    e.scale = number(t, "scale", where);
    e.pathLength = number(t, "path_length_m", where);
    e.ate.translation = stats(t, "ate_translation_m", where);
    e.ate.rotationDeg = stats(t, "ate_rotation_deg", where);
    e.ate.along = stats(t, "ate_along_m", where);
    e.ate.lateral = stats(t, "ate_lateral_m", where);
    e.rpe10 = rpe(t, "rpe_10m", where);
    e.rpe100 = rpe(t, "rpe_100m", where);
    return e;
  }

  Eigen::Vector3d vector3(const json& obj, const char* key, const std::string& where, double nonFinite) const {
    const json& v = array(obj, key, where);
    if (v.size() != 3) throw Error(file_, where + "." + key + " does not have 3 numbers");
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
      out(i) = v[i].is_null() ? nonFinite : json_reading::number(v[i], where + "." + key, file_);
    }
    return out;
  }

 private:
  std::string file_;
};

}  // namespace

std::filesystem::path logEvaluationFile(const std::filesystem::path& out, const std::string& logId) {
  return out / (logId + ".result.json");
}

void writeLogEvaluation(const std::filesystem::path& file, const LogEvaluation& log) {
  json j = {{"log", log.id}, {"path", log.path.string()}, {"error", log.error}};
  if (log.ok()) {
    j["sweeps"] = log.sweeps;
    j["skipped_sweeps"] = log.skippedSweeps;
    if (log.odometry) j["odometry"] = trajectoryJson(*log.odometry);
    if (log.optimized) j["optimized"] = trajectoryJson(*log.optimized);
    j["matches"] = {{"accepted", log.matchesAccepted}, {"degenerate", log.matchesDegenerate}, {"rejected", log.matchesRejected}};
    json priors = json::array();
    for (const MatchErrorSample& s : log.priorErrors) priors.push_back(priorErrorJson(s));
    j["prior_errors"] = priors;
    j["pipeline_s"] = log.pipelineSeconds;
    if (log.mapCheck) {
      const ChangeScore& c = log.mapCheck->score;
      const ChangeScore& x = log.mapCheck->crossings;
      const ChangeScore& l = log.mapCheck->laneLines;
      j["map_check"] = {{"labelled", log.mapCheck->labelled}, {"reports", c.reports}, {"reports_near_change", c.reportsNearChange},
                        {"changes", c.changes}, {"changes_found", c.changesFound}, {"driven_km", c.drivenKm},
                        {"crossings", {{"reports", x.reports}, {"reports_near_change", x.reportsNearChange},
                                       {"changes", x.changes}, {"changes_found", x.changesFound}}},
                        {"lane_lines", {{"reports", l.reports}, {"reports_near_change", l.reportsNearChange},
                                        {"changes", l.changes}, {"changes_found", l.changesFound}}}};
    }
  }
  writeFileAtomically(file, j.dump(1) + "\n");
}

LogEvaluation readLogEvaluation(const std::filesystem::path& file) {
  const json j = json_reading::parse(readFileText(file), file.string());
  const Reader r(file.string());
  LogEvaluation log;
  log.id = r.text(j, "log", "the result");
  log.path = r.text(j, "path", "the result");
  log.error = r.text(j, "error", "the result");
  if (!log.ok()) return log;
  log.sweeps = r.count(j, "sweeps", "the result");
  for (const json& s : r.array(j, "skipped_sweeps", "the result")) {
    if (!s.is_string()) throw Error(file.string(), "the result.skipped_sweeps has an entry that is not a string");
    log.skippedSweeps.push_back(s.get<std::string>());
  }
  if (j.contains("odometry")) log.odometry = r.trajectory(j["odometry"], "the result.odometry");
  if (j.contains("optimized")) log.optimized = r.trajectory(j["optimized"], "the result.optimized");
  const json& matches = r.member(j, "matches", "the result");
  log.matchesAccepted = r.count(matches, "accepted", "the result.matches");
  log.matchesDegenerate = r.count(matches, "degenerate", "the result.matches");
  log.matchesRejected = r.count(matches, "rejected", "the result.matches");
  for (const json& p : r.array(j, "prior_errors", "the result")) {
    const double inf = std::numeric_limits<double>::infinity();
    log.priorErrors.push_back({r.vector3(p, "error", "the result.prior_errors[]", std::numeric_limits<double>::quiet_NaN()),
                               r.vector3(p, "sigma", "the result.prior_errors[]", inf)});
  }
  log.pipelineSeconds = r.number(j, "pipeline_s", "the result");
  if (j.contains("map_check")) {
    const json& m = r.member(j, "map_check", "the result");
    const json& labelled = r.member(m, "labelled", "the result.map_check");
    if (!labelled.is_boolean()) throw Error(file.string(), "the result.map_check.labelled is not true or false");
    const json& x = r.member(m, "crossings", "the result.map_check");
    const json& l = r.member(m, "lane_lines", "the result.map_check");
    const char* crossings = "the result.map_check.crossings";
    const char* lines = "the result.map_check.lane_lines";
    const double km = r.number(m, "driven_km", "the result.map_check");
    log.mapCheck = LogEvaluation::MapCheck{{r.count(m, "reports", "the result.map_check"), r.count(m, "reports_near_change", "the result.map_check"),
                                            r.count(m, "changes", "the result.map_check"), r.count(m, "changes_found", "the result.map_check"), km},
                                           {r.count(x, "reports", crossings), r.count(x, "reports_near_change", crossings),
                                            r.count(x, "changes", crossings), r.count(x, "changes_found", crossings), km},
                                           {r.count(l, "reports", lines), r.count(l, "reports_near_change", lines),
                                            r.count(l, "changes", lines), r.count(l, "changes_found", lines), km},
                                           labelled.get<bool>()};
  }
  return log;
}

}  // namespace hdprior
