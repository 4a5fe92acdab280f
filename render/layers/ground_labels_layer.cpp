#include "render/layers/ground_labels_layer.h"

#include <vector>

#include "engine/io/lidar_sweep.h"
#include "engine/lidar/sweep_road_points.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {
namespace {

const std::array<Eigen::Vector4f, 4> kColours = {
    Eigen::Vector4f(0.55f, 0.55f, 0.58f, 0.6f),  // neither: grey
    Eigen::Vector4f(0.20f, 0.80f, 0.30f, 1.0f),  // both: green
    Eigen::Vector4f(1.00f, 0.70f, 0.10f, 1.0f),  // reference ground missed: amber
    Eigen::Vector4f(0.95f, 0.15f, 0.15f, 1.0f),  // labelled ground, the reference says not: red
};

}  // namespace

void GroundLabelsLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!points_) points_ = std::make_unique<GpuMesh>();
  counts_ = {};
  std::vector<ColoredVertex> vertices;
  if (frame.sweep && frame.index == scene.groundLabelsFrame && scene.groundLabels.size() == frame.sweep->points.size()) {
    const LabelledSweep labelled = labelSweep(*frame.sweep, Eigen::Matrix3d::Identity(), scene.roadPoints);
    const std::vector<uint8_t>& flags = compared_ == RoadPoints ? labelled.road : labelled.ground;
    std::array<std::vector<ColoredVertex>, 4> byAgreement;
    for (size_t i = 0; i < flags.size(); ++i) {
      const bool yes = flags[i] != 0, truth = scene.groundLabels[i] != 0;
      const int a = yes ? (truth ? Both : False) : (truth ? Missed : Neither);
      const LidarPoint& p = frame.sweep->points[i];
      byAgreement[size_t(a)].push_back({scene.local(frame.cityTEgo * Eigen::Vector3d(p.x, p.y, p.z)), kColours[size_t(a)]});
    }
    for (size_t a = 0; a < byAgreement.size(); ++a) {
      counts_[a] = byAgreement[a].size();
      vertices.insert(vertices.end(), byAgreement[a].begin(), byAgreement[a].end());
    }
  }
  points_->upload(std::span<const ColoredVertex>(vertices));
}

void GroundLabelsLayer::draw(const DrawContext& context) const {
  if (points_) drawLidarPoints(context, *points_, pointSize_);
}

std::vector<LayerOption> GroundLabelsLayer::options() {
  return {LayerOption::choice("compare", &compared_, {"ground segmentation", "road points"}, true),
          LayerOption::slider("point size", &pointSize_, 1.0f, 6.0f)};
}

std::vector<MarkerKey> GroundLabelsLayer::markerKeys() const {
  if (!points_ || points_->size() == 0) return {};
  const char* what = compared_ == RoadPoints ? "road point" : "ground";
  return {{std::string(what) + ", labelled ground (" + std::to_string(counts_[Both]) + ")", kColours[Both]},
          {std::string(what) + ", labelled not (" + std::to_string(counts_[False]) + ")", kColours[False]},
          {"labelled ground, missed (" + std::to_string(counts_[Missed]) + ")", kColours[Missed]}};
}

}  // namespace hdprior::render
