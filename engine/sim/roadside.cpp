#include "engine/sim/roadside.h"

#include <cmath>
#include <numbers>
#include <random>
#include <unordered_set>

#include "engine/geom/smoothstep.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kCell = 0.5;  // metres, of the fields' grid

// A band-limited field in [-1, 1]: waves of random direction and phase with wavelengths in
// [minWavelength, maxWavelength], amplitudes summing to 1.
template <class Wave>
std::vector<Wave> randomWaves(int count, double minWavelength, double maxWavelength, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Wave> waves;
  double total = 0.0;
  for (int i = 0; i < count; ++i) {
    const double wavelength = minWavelength + (maxWavelength - minWavelength) * unit(rng);
    const double angle = 2.0 * std::numbers::pi * unit(rng);
    Wave w;
    w.k = Vec2(std::cos(angle), std::sin(angle)) * (2.0 * std::numbers::pi / wavelength);
    w.amplitude = 0.5 + unit(rng);
    w.phase = 2.0 * std::numbers::pi * unit(rng);
    total += w.amplitude;
    waves.push_back(w);
  }
  for (Wave& w : waves) w.amplitude /= total;
  return waves;
}

// A sine whose phase wanders: in [-1, 1], distributed close to a plain sine's (arcsine law),
// so {p : stretchField(p) < sin(pi (f - 1/2))} covers about a fraction f of the streets in
// irregular stretches.
struct StretchField {
  Vec2 k1, k2;
  double phase1 = 0.0, phase2 = 0.0;
  StretchField(double wavelength, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double a1 = 2.0 * std::numbers::pi * unit(rng), a2 = 2.0 * std::numbers::pi * unit(rng);
    k1 = Vec2(std::cos(a1), std::sin(a1)) * (2.0 * std::numbers::pi / wavelength);
    k2 = Vec2(std::cos(a2), std::sin(a2)) * (2.0 * std::numbers::pi / (1.7 * wavelength));
    phase1 = 2.0 * std::numbers::pi * unit(rng);
    phase2 = 2.0 * std::numbers::pi * unit(rng);
  }
  double operator()(const Vec2& p) const { return std::sin(k1.dot(p) + phase1 + 0.8 * std::sin(k2.dot(p) + phase2)); }
  // 1 inside the stretches covering `fraction`, 0 outside, a smooth edge between.
  double in(const Vec2& p, double fraction) const {
    if (fraction <= 0.0) return 0.0;
    if (fraction >= 1.0) return 1.0;
    return smoothstep((std::sin(std::numbers::pi * (fraction - 0.5)) - (*this)(p)) / 0.2 + 0.5);
  }
};

// Kerb cuts: centres among the kerb points thinned to one per 2 m cell, each a cut with
// probability 2 / spacing; returns (centre, length).
std::vector<std::pair<Vec2, double>> kerbCuts(const RoadsideOptions& o, std::span<const Vec2> kerbPoints,
                                              std::mt19937_64& rng) {
  std::vector<std::pair<Vec2, double>> cuts;
  if (o.kerbCutSpacing <= 0.0) return cuts;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::unordered_set<int64_t> seen;
  for (const Vec2& p : kerbPoints) {
    const int64_t key = (int64_t(std::floor(p.x() / 2.0)) << 32) ^ int64_t(uint32_t(int32_t(std::floor(p.y() / 2.0))));
    if (!seen.insert(key).second) continue;
    const double u = unit(rng), length = o.kerbCutLengthMin + (o.kerbCutLengthMax - o.kerbCutLengthMin) * unit(rng);
    if (u < 2.0 / o.kerbCutSpacing) cuts.emplace_back(p, length);
  }
  return cuts;
}

}  // namespace

double TrafficIsland::inside(const Vec2& p) const {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 1e-12 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return radius - (p - (a + t * ab)).norm();
}

double Roadside::sum(const std::vector<Wave>& waves, const Vec2& p) {
  double v = 0.0;
  for (const Wave& w : waves) v += w.amplitude * std::sin(w.k.dot(p) + w.phase);
  return v;
}

double Roadside::mapErrorField(const Vec2& city) const { return options_.mapErrorAmplitude * sum(mapError_, city); }

Roadside Roadside::build(const RoadsideOptions& o, const Vec2& lo, const Vec2& hi, std::span<const Vec2> kerbPoints,
                         std::span<const TrafficIsland> islands, uint64_t seed) {
  Roadside r;
  r.options_ = o;
  r.islands_.assign(islands.begin(), islands.end());
  std::mt19937_64 rng(seed ^ 0x6b657262ULL);
  r.mapError_ = randomWaves<Wave>(3, 0.8 * o.mapErrorWavelength, 1.25 * o.mapErrorWavelength, rng);
  const auto kerbWaves = randomWaves<Wave>(2, 0.7 * o.kerbWavelength, 1.4 * o.kerbWavelength, rng);
  const auto sidewalkWaves = randomWaves<Wave>(2, 60.0, 160.0, rng);
  const auto reliefWaves = randomWaves<Wave>(3, 8.0, 20.0, rng);
  const StretchField noKerb(160.0, rng), mountable(120.0, rng);
  const auto cuts = kerbCuts(o, kerbPoints, rng);

  GridGeometry& g = r.grid_;
  g.resolution = kCell;
  g.origin = (lo / kCell).array().floor() * kCell;
  g.cols = int(std::ceil((hi.x() - g.origin.x()) / kCell)) + 1;
  g.rows = int(std::ceil((hi.y() - g.origin.y()) / kCell)) + 1;
  r.cells_.resize(g.cellCount());
  for (int row = 0; row < g.rows; ++row)
    for (int col = 0; col < g.cols; ++col) {
      const Vec2 p = g.cellCentre(col, row);
      Sample& s = r.cells_[g.index(col, row)];
      s.mapOffset = float(o.mapErrorAmplitude * sum(r.mapError_, p));
      const double height = o.kerbHeightMin + (o.kerbHeightMax - o.kerbHeightMin) * 0.5 * (1.0 + sum(kerbWaves, p));
      s.kerbHeight = float(height * (1.0 - noKerb.in(p, o.noKerbFraction)));
      s.kerbSlopeWidth = float(o.mountableWidth * mountable.in(p, o.mountableFraction));
      s.sidewalkWidth = float(o.sidewalkWidthMin + (o.sidewalkWidthMax - o.sidewalkWidthMin) * 0.5 * (1.0 + sum(sidewalkWaves, p)));
      s.relief = float(o.terrainRelief * sum(reliefWaves, p));
      double island = -1e3;
      for (const TrafficIsland& t : r.islands_) island = std::max(island, t.inside(p));
      s.island = float(island);
    }
  // The kerb ramps down to nothing over the last metre into each cut.
  for (const auto& [centre, length] : cuts) {
    const double outer = 0.5 * length, inner = std::max(0.0, outer - 1.0);
    const int c0 = std::max(0, int(std::floor((centre.x() - outer - g.origin.x()) / kCell)));
    const int c1 = std::min(g.cols - 1, int(std::floor((centre.x() + outer - g.origin.x()) / kCell)));
    const int r0 = std::max(0, int(std::floor((centre.y() - outer - g.origin.y()) / kCell)));
    const int r1 = std::min(g.rows - 1, int(std::floor((centre.y() + outer - g.origin.y()) / kCell)));
    for (int row = r0; row <= r1; ++row)
      for (int col = c0; col <= c1; ++col) {
        const double d = (g.cellCentre(col, row) - centre).norm();
        r.cells_[g.index(col, row)].kerbHeight *= float(smoothstep((d - inner) / std::max(1e-6, outer - inner)));
      }
  }
  const double reliefSlope = o.terrainRelief * 2.0 * std::numbers::pi / 8.0;
  r.maxRise_ = std::max(o.camber * o.camberCap,
                        std::max(o.kerbHeightMax, 0.0) + o.sidewalkSlope * o.sidewalkWidthMax + std::abs(o.terrainRelief));
  r.maxSlope_ = o.camber + o.sidewalkSlope + reliefSlope + 0.01;
  return r;
}

Roadside::Sample Roadside::at(const Vec2& city) const {
  const Vec2 u = grid_.toCell(city) - Vec2(0.5, 0.5);
  const double x = std::clamp(u.x(), 0.0, double(grid_.cols - 1));
  const double y = std::clamp(u.y(), 0.0, double(grid_.rows - 1));
  const int c0 = std::min(int(x), std::max(0, grid_.cols - 2)), r0 = std::min(int(y), std::max(0, grid_.rows - 2));
  const int c1 = std::min(c0 + 1, grid_.cols - 1), r1 = std::min(r0 + 1, grid_.rows - 1);
  const float fx = float(x - c0), fy = float(y - r0);
  const float w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
  const Sample &a = cells_[grid_.index(c0, r0)], &b = cells_[grid_.index(c1, r0)];
  const Sample &c = cells_[grid_.index(c0, r1)], &d = cells_[grid_.index(c1, r1)];
  const auto mix = [&](float Sample::*f) { return w00 * a.*f + w10 * b.*f + w01 * c.*f + w11 * d.*f; };
  return {mix(&Sample::mapOffset), mix(&Sample::kerbHeight), mix(&Sample::kerbSlopeWidth),
          mix(&Sample::sidewalkWidth), mix(&Sample::island), mix(&Sample::relief)};
}

double Roadside::rise(double d, const Sample& s) const {
  const RoadsideOptions& o = options_;
  if (d < 0.0) {
    const double u = -d;
    double h = o.camber * std::min(u, o.camberCap);
    if (u < o.gutterWidth) h -= o.gutterDepth * (1.0 - u / o.gutterWidth);
    return h;
  }
  const double slopeWidth = s.kerbSlopeWidth;
  double h = slopeWidth > 0.05 ? s.kerbHeight * std::min(d / slopeWidth, 1.0) : double(s.kerbHeight);
  h += o.sidewalkSlope * std::min(d, double(s.sidewalkWidth));
  if (d > s.sidewalkWidth) h += s.relief * std::min(d - s.sidewalkWidth, 1.0);
  return h;
}

}  // namespace hdprior
