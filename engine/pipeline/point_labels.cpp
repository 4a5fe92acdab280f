#include "engine/pipeline/point_labels.h"

#include "engine/geom/se2.h"

namespace hdprior {

std::vector<SubmapLabel> pointLabels(const LabelledSubmap& submap) {
  std::vector<SubmapLabel> labels(submap.points.size(), SubmapLabel::Other);
  for (size_t i = 0; i < labels.size(); ++i) {
    if (submap.road[i] == kCurbPoint) labels[i] = SubmapLabel::Curb;
    else if (submap.road[i] == kRoadPoint) labels[i] = SubmapLabel::Road;
    else if (submap.ground[i]) labels[i] = SubmapLabel::Ground;
  }
  return labels;
}

std::vector<SubmapLabel> sweepPointLabels(const LidarSweep& sweep, const SE3& cityTEgo, const SweepRoadPointOptions& options) {
  const SubmapSweep one{&sweep, levelRotation(cityTEgo), Eigen::Vector3d::Zero()};
  return pointLabels(labelSubmap(std::span<const SubmapSweep>(&one, 1), options));
}

const char* labelName(SubmapLabel label) {
  switch (label) {
    case SubmapLabel::Road: return "road";
    case SubmapLabel::Curb: return "curb";
    case SubmapLabel::Ground: return "other ground";
    case SubmapLabel::Other: break;
  }
  return "non-ground";
}

}  // namespace hdprior
