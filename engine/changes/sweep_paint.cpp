#include "engine/changes/sweep_paint.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace hdprior {

namespace {

constexpr size_t kRingPointsForMedian = 50;  // fewer road points of a ring take the sweep's median

uint8_t medianIntensity(const LidarSweep& sweep, const std::vector<size_t>& near) {
  std::vector<uint8_t> values;
  values.reserve(near.size());
  for (size_t i : near) values.push_back(sweep.points[i].intensity);
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
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
  const uint8_t sweepMedian = medianIntensity(sweep, near);
  std::vector<bool> bright(labelled.points.size(), false);
  std::vector<double> azimuth(labelled.points.size(), 0.0);
  std::map<uint8_t, std::vector<size_t>> rings;
  for (size_t i : near) {
    paint.road.push_back(labelled.points[i].head<2>());
    azimuth[i] = std::atan2(labelled.points[i].y(), labelled.points[i].x());
    rings[sweep.points[i].laserNumber].push_back(i);
  }
  for (auto& [laser, ring] : rings) {
    // Each ring against its own asphalt: a near ring meets the road at a steeper angle and returns
    // more from it, a far one less (against the sweep's median, paint 10 m off went unseen).
    const double threshold = options.paintContrast * (ring.size() >= kRingPointsForMedian ? medianIntensity(sweep, ring) : sweepMedian);
    for (size_t i : ring) bright[i] = sweep.points[i].intensity > threshold;
    std::sort(ring.begin(), ring.end(), [&](size_t a, size_t b) { return azimuth[a] < azimuth[b]; });
    addRuns(ring, bright, labelled, options, paint.runs);
  }
  return paint;
}

}  // namespace hdprior
