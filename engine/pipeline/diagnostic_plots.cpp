#include "engine/pipeline/diagnostic_plots.h"

#include <algorithm>

#include "engine/error.h"

namespace hdprior {

const std::vector<DiagnosticPlot>& diagnosticPlots() {
  using F = DiagnosticField;
  static const std::vector<DiagnosticPlot> plots = {
      {"score", "NDT score per point", {{F::ScorePerPoint, "score"}}, std::nullopt},
      {"inliers", "inlier ratio", {{F::InlierRatio, "inliers"}}, std::nullopt},
      {"road_points", "road points", {{F::RoadPoints, "road"}}, std::nullopt},
      {"curb_points", "curb points", {{F::CurbPoints, "curb"}}, std::nullopt},
      {"sigma_along", "sigma along (m)", {{F::SigmaAlong, "sigma"}}, std::nullopt},
      {"sigma_lateral", "sigma lateral (m)", {{F::SigmaLateral, "sigma"}}, std::nullopt},
      {"sigma_yaw", "sigma yaw (deg)", {{F::SigmaYawDeg, "sigma"}}, std::nullopt},
      {"chi2", "innovation chi2 (line: gate)", {{F::InnovationChi2, "chi2"}}, F::GateQuantile},
      {"residual", "prior residual chi2, optimised", {{F::ResidualChi2, "residual"}}, std::nullopt},
      {"error_along", "error along (m)", {{F::MatchErrorAlong, "match"}, {F::PriorErrorAlong, "prior"}}, std::nullopt},
      {"error_lateral", "error lateral (m)", {{F::MatchErrorLateral, "match"}, {F::PriorErrorLateral, "prior"}}, std::nullopt},
      {"error_yaw", "error yaw (deg)", {{F::MatchErrorYawDeg, "match"}, {F::PriorErrorYawDeg, "prior"}}, std::nullopt},
      {"ate_along", "keyframe ATE along (m)", {{F::AteAlong, "ate"}}, std::nullopt},
      {"ate_lateral", "keyframe ATE lateral (m)", {{F::AteLateral, "ate"}}, std::nullopt},
  };
  return plots;
}

const DiagnosticPlot* findDiagnosticPlot(std::string_view name) {
  for (const DiagnosticPlot& p : diagnosticPlots())
    if (name == p.name) return &p;
  return nullptr;
}

std::string diagnosticPlotNames() {
  std::string s;
  for (const DiagnosticPlot& p : diagnosticPlots()) s += (s.empty() ? "" : ", ") + std::string(p.name);
  return s;
}

std::vector<const DiagnosticPlot*> parseDiagnosticPlotList(std::string_view list, const std::string& where) {
  std::vector<const DiagnosticPlot*> plots;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find(',', start), list.size());
    const std::string_view name = list.substr(start, end - start);
    if (name.empty()) throw Error(where, "empty plot name in '" + std::string(list) + "' (plots: " + diagnosticPlotNames() + ")");
    const DiagnosticPlot* plot = findDiagnosticPlot(name);
    if (!plot) throw Error(where, "unknown plot '" + std::string(name) + "' (plots: " + diagnosticPlotNames() + ")");
    if (std::find(plots.begin(), plots.end(), plot) == plots.end()) plots.push_back(plot);
    start = end + 1;
  }
  return plots;
}

}  // namespace hdprior
