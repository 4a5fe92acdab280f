#include "engine/changes/ground_brightness.h"

#include <algorithm>
#include <map>

namespace hdprior {

namespace {

constexpr size_t kRingRoadPoints = 50;  // fewer road points of a ring take the sweep's quartile

double lowerQuartile(std::vector<uint8_t> values) {
  if (values.empty()) return 1.0;
  std::nth_element(values.begin(), values.begin() + long(values.size() / 4), values.end());
  return std::max(1.0, double(values[values.size() / 4]));
}

}  // namespace

std::vector<float> groundBrightness(const LidarSweep& sweep, const LabelledSweep& labelled) {
  std::map<uint8_t, std::vector<uint8_t>> ringRoad;
  std::vector<uint8_t> road;
  for (size_t i = 0; i < labelled.points.size(); ++i)
    if (labelled.road[i]) ringRoad[sweep.points[i].laserNumber].push_back(sweep.points[i].intensity), road.push_back(sweep.points[i].intensity);
  const double sweepAsphalt = lowerQuartile(std::move(road));
  std::map<uint8_t, double> asphalt;
  for (auto& [laser, values] : ringRoad) asphalt[laser] = values.size() >= kRingRoadPoints ? lowerQuartile(std::move(values)) : sweepAsphalt;
  std::vector<float> out(labelled.points.size(), 0.0f);
  for (size_t i = 0; i < labelled.points.size(); ++i) {
    if (!labelled.ground[i]) continue;
    const auto a = asphalt.find(sweep.points[i].laserNumber);
    out[i] = float(sweep.points[i].intensity / (a == asphalt.end() ? sweepAsphalt : a->second));
  }
  return out;
}

}  // namespace hdprior
