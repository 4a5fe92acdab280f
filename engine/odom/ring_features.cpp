#include "engine/odom/ring_features.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "engine/odom/parallel_for.h"

namespace hdprior {
namespace {

constexpr double kPi = 3.14159265358979323846;

double azimuthStep(float a, float b) {
  double d = std::abs(double(b) - double(a));
  return d > kPi ? 2 * kPi - d : d;
}

// Marks points whose neighbourhood is not trustworthy: out of range, across a ring gap, on the
// far side of an occlusion edge, or hit by a beam nearly parallel to the surface.
std::vector<bool> rejectedPoints(const std::vector<RingPoint>& ring, const std::vector<float>& range,
                                 const FeatureOptions& o) {
  const int n = int(ring.size()), k = o.neighbours;
  std::vector<bool> bad(n, false);
  const double maxGap = o.maxGapDeg * kPi / 180.0;
  for (int i = 0; i < n; ++i) bad[i] = range[i] < o.minRange || range[i] > o.maxRange;
  for (int i = 0; i + 1 < n; ++i) {
    if (azimuthStep(ring[i].azimuth, ring[i + 1].azimuth) > maxGap) {
      for (int j = std::max(0, i - k + 1); j <= std::min(n - 1, i + k); ++j) bad[j] = true;
      continue;
    }
    const float d1 = range[i], d2 = range[i + 1];
    if (std::abs(d1 - d2) > o.occlusionRatio * std::min(d1, d2)) {
      if (d1 > d2) {
        for (int j = std::max(0, i - k + 1); j <= i; ++j) bad[j] = true;
      } else {
        for (int j = i + 1; j <= std::min(n - 1, i + k); ++j) bad[j] = true;
      }
    }
  }
  for (int i = 1; i + 1 < n; ++i) {
    const double limit = o.parallelBeamRatio * range[i];
    if ((ring[i].p - ring[i - 1].p).norm() > limit && (ring[i + 1].p - ring[i].p).norm() > limit) bad[i] = true;
  }
  return bad;
}

// Suppresses the neighbours of a picked feature along the ring, up to a jump in the ring.
void suppressNeighbours(const std::vector<RingPoint>& ring, int i, int k, std::vector<bool>& picked) {
  const int n = int(ring.size());
  picked[i] = true;
  for (int l = 1; l <= k && i + l < n; ++l) {
    if ((ring[i + l].p - ring[i + l - 1].p).squaredNorm() > 0.05f) break;
    picked[i + l] = true;
  }
  for (int l = 1; l <= k && i - l >= 0; ++l) {
    if ((ring[i - l].p - ring[i - l + 1].p).squaredNorm() > 0.05f) break;
    picked[i - l] = true;
  }
}

}  // namespace

std::vector<FeatureLabel> labelRing(const std::vector<RingPoint>& ring, const FeatureOptions& o) {
  const int n = int(ring.size()), k = std::max(1, o.neighbours);
  std::vector<FeatureLabel> labels(n, FeatureLabel::None);
  if (n < 2 * k + 1) return labels;
  std::vector<float> range(n);
  for (int i = 0; i < n; ++i) range[i] = ring[i].p.norm();
  const std::vector<bool> bad = rejectedPoints(ring, range, o);

  std::vector<float> curvature(n, -1.f);
  for (int i = k; i < n - k; ++i) {
    bool ok = true;
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    for (int j = i - k; j <= i + k && ok; ++j) {
      ok = !bad[j];
      sum += ring[j].p - ring[i].p;
    }
    if (ok) curvature[i] = sum.norm() / (2.f * k * range[i]);
  }

  std::vector<bool> picked(n, false);
  const int sectors = std::max(1, o.sectors);
  std::vector<int> order;
  for (int s = 0; s < sectors; ++s) {
    const int begin = k + (n - 2 * k) * s / sectors, end = k + (n - 2 * k) * (s + 1) / sectors;
    order.resize(end - begin);
    std::iota(order.begin(), order.end(), begin);
    // Most curved first (ties by index); the flats are taken from the other end.
    std::sort(order.begin(), order.end(), [&](int a, int b) { return curvature[a] > curvature[b] || (curvature[a] == curvature[b] && a < b); });
    int planes = 0;
    for (auto it = order.rbegin(); it != order.rend() && planes < o.flatPerSector; ++it) {
      const int i = *it;
      if (curvature[i] < 0) continue;
      if (curvature[i] >= o.planeCurvature) break;
      if (picked[i]) continue;
      ++planes;
      labels[i] = FeatureLabel::Flat;
      suppressNeighbours(ring, i, k, picked);
    }
  }
  for (int i = 0; i < n; ++i) {
    if (labels[i] == FeatureLabel::None && curvature[i] >= 0 && curvature[i] < o.edgeCurvature) labels[i] = FeatureLabel::LessFlat;
  }
  return labels;
}

FeatureCloud extractFeatures(const std::vector<Eigen::Vector3f>& points, const std::vector<LidarPoint>& raw,
                             const FeatureOptions& options, int threads) {
  std::array<std::vector<uint32_t>, 256> byLaser;
  for (uint32_t i = 0; i < raw.size(); ++i) byLaser[raw[i].laserNumber].push_back(i);
  std::vector<std::vector<uint32_t>*> rings;
  for (auto& indices : byLaser) {
    if (!indices.empty()) rings.push_back(&indices);
  }
  std::vector<std::vector<RingPoint>> ringPoints(rings.size());
  std::vector<std::vector<FeatureLabel>> labels(rings.size());
  parallelFor(rings.size(), threads, [&](size_t begin, size_t end) {
    for (size_t r = begin; r < end; ++r) {
      auto& indices = *rings[r];
      std::stable_sort(indices.begin(), indices.end(), [&](uint32_t a, uint32_t b) { return raw[a].offsetNs < raw[b].offsetNs; });
      auto& ring = ringPoints[r];
      ring.resize(indices.size());
      for (size_t j = 0; j < indices.size(); ++j) {
        const Eigen::Vector3f& p = points[indices[j]];
        ring[j] = {p, std::atan2(p.y(), p.x())};
      }
      labels[r] = labelRing(ring, options);
    }
  }, 1);
  FeatureCloud cloud;
  for (size_t r = 0; r < rings.size(); ++r) {
    for (size_t j = 0; j < ringPoints[r].size(); ++j) {
      const Eigen::Vector3f& p = ringPoints[r][j].p;
      switch (labels[r][j]) {
        case FeatureLabel::Flat: cloud.flat.push_back(p); [[fallthrough]];
        case FeatureLabel::LessFlat: cloud.lessFlat.push_back(p); break;
        case FeatureLabel::None: break;
      }
    }
  }
  return cloud;
}

}  // namespace hdprior
