#include "engine/pipeline/point_labels.h"

#include "engine/geom/se2.h"

namespace hdprior {

std::vector<SubmapLabel> pointLabels(const LabelledSweep& sweep) {
  std::vector<SubmapLabel> labels(sweep.points.size(), SubmapLabel::Other);
  for (size_t i = 0; i < labels.size(); ++i) {
    if (sweep.road[i] == kCurbPoint) labels[i] = SubmapLabel::Curb;
    else if (sweep.road[i] == kRoadPoint) labels[i] = SubmapLabel::Road;
    else if (sweep.ground[i]) labels[i] = SubmapLabel::Ground;
  }
  return labels;
}

std::vector<SubmapLabel> sweepPointLabels(const LidarSweep& sweep, const SE3& cityTEgo, const SweepRoadPointOptions& options) {
  return pointLabels(labelSweep(sweep, levelRotation(cityTEgo), options));
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
