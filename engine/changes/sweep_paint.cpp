#include "engine/changes/sweep_paint.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace hdprior {

namespace {

constexpr size_t kRingPointsForMedian = 50;  // fewer road points of a ring take the sweep's median

// The intensity below which `share` of the points lie (0.5: the median).
uint8_t intensityQuantile(const LidarSweep& sweep, const std::vector<size_t>& near, double share) {
  std::vector<uint8_t> values;
  values.reserve(near.size());
  for (size_t i : near) values.push_back(sweep.points[i].intensity);
  const auto at = values.begin() + std::ptrdiff_t(share * double(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

// Runs of bright returns in one ring's road points near the sensor (`ring`, in azimuth order).
void addRuns(const std::vector<size_t>& ring, const std::vector<bool>& bright, const LabelledSweep& labelled,
             const ChangeOptions& options, std::vector<PaintRun>& runs) {
  size_t start = 0;
  while (start < ring.size()) {
    size_t end = start;
    if (bright[ring[start]]) {
      while (end + 1 < ring.size() && bright[ring[end + 1]] &&
             (labelled.points[ring[end + 1]] - labelled.points[ring[end]]).head<2>().norm() <= options.paintRunGap)
        ++end;
      const int count = int(end - start + 1);
      if (count >= options.paintRunPoints) {
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        for (size_t k = start; k <= end; ++k) sum += labelled.points[ring[k]].head<2>();
        runs.push_back({sum / count, count});
      }
    }
    start = end + 1;
  }
}

}  // namespace

SweepPaint findSweepPaint(const LidarSweep& sweep, const LabelledSweep& labelled, const ChangeOptions& options) {
  SweepPaint paint;
  std::vector<size_t> near;
  for (size_t i = 0; i < labelled.points.size(); ++i)
    if (labelled.road[i] && labelled.points[i].head<2>().norm() <= options.paintRange) near.push_back(i);
  if (near.empty()) return paint;
  const uint8_t sweepMedian = intensityQuantile(sweep, near, 0.5), sweepQuartile = intensityQuantile(sweep, near, 0.25);
  std::vector<bool> bright(labelled.points.size(), false);
  std::vector<double> azimuth(labelled.points.size(), 0.0);
  std::map<uint8_t, std::vector<size_t>> rings;
  for (size_t i : near) {
    paint.road.push_back(labelled.points[i].head<2>());
    azimuth[i] = std::atan2(labelled.points[i].y(), labelled.points[i].x());
    rings[sweep.points[i].laserNumber].push_back(i);
  }
  std::vector<float> brightness(labelled.points.size(), 0.0f);
  for (auto& [laser, ring] : rings) {
    // Each ring against its own asphalt: a near ring meets the road at a steeper angle and returns
    // more from it, a far one less (against the sweep's median, paint 10 m off went unseen).
    const bool own = ring.size() >= kRingPointsForMedian;
    const double threshold = options.paintContrast * (own ? intensityQuantile(sweep, ring, 0.5) : sweepMedian);
    // Brightness against the lower quartile: a crossing seen head-on fills much of a ring and lifts its median.
    const double asphalt = std::max<double>(1.0, own ? intensityQuantile(sweep, ring, 0.25) : sweepQuartile);
    for (size_t i : ring) {
      bright[i] = sweep.points[i].intensity > threshold;
      brightness[i] = float(sweep.points[i].intensity / asphalt);
    }
    std::sort(ring.begin(), ring.end(), [&](size_t a, size_t b) { return azimuth[a] < azimuth[b]; });
    addRuns(ring, bright, labelled, options, paint.runs);
  }
  for (size_t i : near) paint.brightness.push_back(brightness[i]);
  return paint;
}

}  // namespace hdprior
