#pragma once
#include <vector>

#include "engine/geom/se3.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/pipeline/keyframe_inspection.h"

namespace hdprior {

// One label per point of a labelled sweep: curb, road, other ground or other.
std::vector<SubmapLabel> pointLabels(const LabelledSweep& sweep);

// A single sweep's points labelled as the road points label them (ground segmentation, then the
// road walk), levelled with the roll and pitch of cityTEgo. One label per sweep point, in order.
std::vector<SubmapLabel> sweepPointLabels(const LidarSweep& sweep, const SE3& cityTEgo, const SweepRoadPointOptions& options);

// "road", "curb", "other ground", "non-ground".
const char* labelName(SubmapLabel label);

}  // namespace hdprior
