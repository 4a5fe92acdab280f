#include "engine/changes/polygon_offset.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace hdprior {

namespace {

double residual(const EdgeOffset& e, const Eigen::Vector2d& t) { return e.normal.dot(t) - e.offset; }

// Least squares with Huber weights (the band as the scale): a few edges the walk placed wrong do
// not pull the translation. A direction no sample observes stays at zero (the small ridge).
Eigen::Vector2d robustTranslation(const std::vector<EdgeOffset>& samples, double band) {
  Eigen::Vector2d t = Eigen::Vector2d::Zero();
  std::vector<double> weight(samples.size(), 1.0);
  for (int iteration = 0; iteration < 20; ++iteration) {
    Eigen::Matrix2d a = 1e-3 * Eigen::Matrix2d::Identity();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (size_t i = 0; i < samples.size(); ++i) {
      a += weight[i] * samples[i].normal * samples[i].normal.transpose();
      b += weight[i] * samples[i].offset * samples[i].normal;
    }
    t = a.ldlt().solve(b);
    for (size_t i = 0; i < samples.size(); ++i) weight[i] = std::min(1.0, band / std::max(1e-9, std::abs(residual(samples[i], t))));
  }
  return t;
}

bool near(const EdgeOffset& e, const std::vector<EdgeOffset>& samples, double reach) {
  return std::any_of(samples.begin(), samples.end(), [&](const EdgeOffset& s) { return (s.point - e.point).squaredNorm() < reach * reach; });
}

// More edges around that the translation moves lie where it puts them than where the map does.
bool posesOff(const PolygonOffset& p, const std::vector<EdgeOffset>& samples, const std::vector<EdgeOffset>& around, const ChangeOptions& o) {
  int follow = 0, onMap = 0;
  for (const EdgeOffset& e : around) {
    if (std::abs(e.normal.dot(p.translation)) < o.polygonFitBand || !near(e, samples, o.polygonNeighbourhood)) continue;
    follow += p.explains(e, o);
    onMap += std::abs(e.offset) < o.polygonFitBand;
  }
  return follow > onMap;
}

}  // namespace

bool PolygonOffset::explains(const EdgeOffset& e, const ChangeOptions& o) const {
  return std::abs(residual(e, translation)) < o.polygonFitBand && std::abs(e.offset) >= o.polygonFitBand;
}

std::optional<PolygonOffset> polygonOffset(const std::vector<EdgeOffset>& samples, const std::vector<EdgeOffset>& around,
                                           const ChangeOptions& o) {
  if (int(samples.size()) < o.polygonMinSamples) return std::nullopt;
  PolygonOffset p;
  p.samples = int(samples.size());
  p.translation = robustTranslation(samples, o.polygonFitBand);
  int fit = 0, moved = 0, movedOnMap = 0;
  for (const EdgeOffset& e : samples) {
    fit += std::abs(residual(e, p.translation)) < o.polygonFitBand;
    if (std::abs(e.normal.dot(p.translation)) < o.polygonFitBand) continue;  // a side along the translation: both agree
    ++moved;
    movedOnMap += std::abs(e.offset) < o.polygonFitBand;
  }
  p.fitShare = double(fit) / p.samples;
  p.mapShare = moved > 0 ? double(movedOnMap) / moved : 1.0;
  if (moved < o.polygonMinSamples) return std::nullopt;
  if (p.translation.norm() < o.polygonShift || p.fitShare < o.polygonFitShare || p.mapShare > o.polygonMapShare) return std::nullopt;
  if (posesOff(p, samples, around, o)) return std::nullopt;
  return p;
}

}  // namespace hdprior
