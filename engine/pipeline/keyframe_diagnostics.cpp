#include "engine/pipeline/keyframe_diagnostics.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/eval/match_calibration.h"
#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/graph/pose_prior.h"
#include "engine/io/file_bytes.h"
#include "engine/pipeline/prior_stage.h"

namespace hdprior {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegree = 180.0 / std::numbers::pi;
using F = DiagnosticField;

double finiteOrNaN(double v) { return std::isfinite(v) ? v : kNaN; }

void setTriple(KeyframeDiagnostic& d, F first, const Eigen::Vector3d& v) {
  d[first] = finiteOrNaN(v(0));
  d[F(size_t(first) + 1)] = finiteOrNaN(v(1));
  d[F(size_t(first) + 2)] = finiteOrNaN(v(2) * kDegree);
}

void setEvidence(KeyframeDiagnostic& d, const KeyframeMatch& m) {
  const MatchResult& r = m.match;
  d[F::ScorePerPoint] = r.scorePerPoint;
  d[F::InlierRatio] = r.inlierRatio;
  d[F::RoadPoints] = double(r.points);
  d[F::CurbPoints] = double(r.curbPoints);
  if (m.hasPrior || m.gated) {
    d[F::InnovationChi2] = m.innovationChi2;
    if (m.gateQuantile > 0) d[F::GateQuantile] = m.gateQuantile;
  }
}

}  // namespace

const char* diagnosticKey(DiagnosticField field) {
  static constexpr const char* keys[kDiagnosticFields] = {
      "score_per_point", "inlier_ratio",    "road_points",      "curb_points",       "sigma_along_m",
      "sigma_lateral_m", "sigma_yaw_deg",   "innovation_chi2",  "gate_quantile",     "residual_chi2",
      "match_error_along_m", "match_error_lateral_m", "match_error_yaw_deg", "prior_error_along_m",
      "prior_error_lateral_m", "prior_error_yaw_deg", "ate_along_m", "ate_lateral_m"};
  return keys[size_t(field)];
}

KeyframeDiagnostic::KeyframeDiagnostic() { values.fill(kNaN); }

std::vector<KeyframeDiagnostic> keyframeDiagnostics(const std::vector<KeyframeMatch>& matches,
                                                    const std::vector<SE3>& keyframePoses, const PoseTrajectory& truth,
                                                    const std::function<size_t(size_t)>& sweepOfFrame) {
  std::vector<KeyframeDiagnostic> rows;
  rows.reserve(matches.size());
  for (const KeyframeMatch& m : matches) {
    KeyframeDiagnostic d;
    d.keyframe = m.keyframe;
    d.frame = sweepOfFrame(m.frame);
    d.constraint = constraintOf(m);
    setEvidence(d, m);
    const bool hasTruth = !truth.empty() && truth.covers(m.timestampNs);
    const Eigen::Vector3d truthPose = hasTruth ? planarPose(truth.at(m.timestampNs)) : Eigen::Vector3d::Zero();
    if (m.hasPrior) {
      const Eigen::Vector3d priorPose = planarPose(m.prior.pose);
      const MatchErrorSample s = matchErrorSample(hasTruth ? truthPose : priorPose, priorPose, marginalPlanarInformation(m.prior));
      setTriple(d, F::SigmaAlong, s.sigma);
      if (hasTruth) setTriple(d, F::PriorErrorAlong, s.error);
      if (m.keyframe < keyframePoses.size()) d[F::ResidualChi2] = priorResidual(m.prior, keyframePoses[m.keyframe]).chi2;
    } else if (m.gated) {
      setTriple(d, F::SigmaAlong, matchErrorSample(m.match.estimate, m.match.estimate, m.match.information).sigma);
    }
    if (hasTruth && m.match.points > 0) setTriple(d, F::MatchErrorAlong, planarError(truthPose, m.match.estimate));
    if (hasTruth && m.keyframe < keyframePoses.size()) {
      const Eigen::Vector3d e = planarError(truthPose, planarPose(keyframePoses[m.keyframe]));
      d[F::AteAlong] = e.x();
      d[F::AteLateral] = e.y();
    }
    rows.push_back(d);
  }
  return rows;
}

namespace {

PriorConstraint constraintFromJson(const nlohmann::json& match) {
  const nlohmann::json& c = match.at("constraint");
  PriorConstraint out;
  const std::string category = c.at("category").get<std::string>();
  out.kind = category == "rejected" ? PriorConstraint::Kind::Rejected
             : category == "gated"  ? PriorConstraint::Kind::Gated
                                    : PriorConstraint::Kind::Fixes;
  out.along = c.at("along").get<bool>();
  out.lateral = c.at("lateral").get<bool>();
  out.yaw = c.at("yaw").get<bool>();
  const std::string label = match.at("constrains").get<std::string>();
  if (out.kind != PriorConstraint::Kind::Fixes && label.size() > category.size() + 2) out.reason = label.substr(category.size() + 2);
  return out;
}

}  // namespace

std::vector<KeyframeDiagnostic> readKeyframeDiagnostics(const std::filesystem::path& file) {
  const std::string text = readFileText(file);
  nlohmann::json keyframes;
  try {
    keyframes = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(file.string(), std::string("not JSON: ") + e.what());
  }
  if (!keyframes.is_array()) throw Error(file.string(), "not a list of keyframes");
  std::vector<KeyframeDiagnostic> rows;
  for (const nlohmann::json& k : keyframes) {
    try {
      if (!k.contains("match")) continue;  // odometry alone: nothing to diagnose
      KeyframeDiagnostic d;
      d.keyframe = k.at("index").get<size_t>();
      d.frame = k.at("frame").get<size_t>();
      d.constraint = constraintFromJson(k.at("match"));
      const nlohmann::json& values = k.at("diagnostics");
      for (size_t f = 0; f < kDiagnosticFields; ++f) {
        const nlohmann::json& v = values.at(diagnosticKey(DiagnosticField(f)));
        d.values[f] = v.is_null() ? kNaN : v.get<double>();
      }
      rows.push_back(d);
    } catch (const nlohmann::json::exception& e) {
      throw Error(file.string(), "keyframe " + std::to_string(rows.size()) + ": " + e.what());
    }
  }
  return rows;
}

}  // namespace hdprior
