#include "render/layers/road_points_layer.h"

#include <vector>

#include <Eigen/Geometry>

#include "engine/pipeline/keyframe_inspection.h"
#include "render/analysis.h"
#include "render/layers/analysis_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void RoadPointsLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  inspection_ = analysis.inspection ? &*analysis.inspection : nullptr;
  build(scene);
}

void RoadPointsLayer::build(const Scene& scene) {
  if (!points_) points_ = std::make_unique<GpuMesh>();
  std::vector<ColoredVertex> vertices;
  if (inspection_) {
    const KeyframeInspection& k = *inspection_;
    const Eigen::Vector3d pose = placement_ == AtStart                 ? k.start
                                 : placement_ == AtTruth && k.truth ? *k.truth
                                                                       : k.match.estimate;
    Eigen::Isometry3d cityTLevel = Eigen::Isometry3d::Identity();
    cityTLevel.linear() = Eigen::AngleAxisd(pose.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    cityTLevel.translation() = Eigen::Vector3d(pose.x(), pose.y(), k.keyframePose.translation().z());
    vertices.reserve(k.points.size());
    // One range per label, drawn in this order (each tinted by its colour): curbs end on top.
    for (size_t r = 0; r < kDrawOrder.size(); ++r) {
      const SubmapLabel label = kDrawOrder[r];
      if (label != SubmapLabel::Other || nonGround_) {
        for (size_t i = 0; i < k.points.size(); ++i)
          if (k.labels[i] == label) vertices.push_back({scene.local(cityTLevel * k.points[i].cast<double>()), Eigen::Vector4f::Ones()});
      }
      rangeEnd_[r] = vertices.size();
    }
  } else {
    rangeEnd_.fill(0);
  }
  points_->upload(std::span<const ColoredVertex>(vertices));
}

void RoadPointsLayer::draw(const DrawContext& context) const {
  if (!points_) return;
  const Eigen::Vector4f* colors[] = {&other_, &ground_, &road_, &curb_};
  drawRanges(context, *points_, Primitive::Points, pointSize_, false, rangeEnd_, colors);
}

std::vector<LayerOption> RoadPointsLayer::options() {
  return {LayerOption::choice("placed at", &placement_, {"match estimate", "match start", "ground truth"}, true),
          LayerOption::choice("non-ground", &nonGround_, {"hidden", "shown"}, true),
          LayerOption::slider("point size", &pointSize_, 1.0f, 6.0f),
          LayerOption::colorPicker("road", &road_),
          LayerOption::colorPicker("curb", &curb_),
          LayerOption::colorPicker("other ground", &ground_),
          LayerOption::colorPicker("non-ground", &other_)};
}

}  // namespace hdprior::render
