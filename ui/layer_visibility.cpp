#include "ui/layer_visibility.h"

#include <algorithm>

#include "render/layer_registry.h"

namespace hdprior::ui {

const std::vector<std::string>& defaultVisibleLayers() {
  static const std::vector<std::string> names = {"sweep", "drivable", "boundary", "ground", "trajectory", "ego"};
  return names;
}

bool hasAnalysisData(const std::string& name, const render::Analysis& analysis) {
  if (name == "odometry_trajectory") return !analysis.odometry.empty();
  if (name == "optimized_trajectory") return !analysis.optimized.empty();
  if (name == "file_trajectory") return !analysis.file.empty();
  if (name == "keyframes") return !analysis.keyframes.empty();
  if (name == "landscape") return analysis.landscape.has_value();
  if (name == "road_points" || name == "match") return analysis.inspection.has_value();
  if (name == "comparison_trajectory") return analysis.comparison && !analysis.comparison->optimized.empty();
  if (name == "comparison_match") return analysis.comparison && analysis.comparison->inspection;
  if (name == "measure") return analysis.measure.has_value();
  if (name == "changes") return analysis.changes != nullptr;
  return false;
}

void LayerVisibility::reset(const Layers& layers) {
  settled_.clear();
  const auto& shown = defaultVisibleLayers();
  for (const auto& layer : layers)
    layer->visible = std::find(shown.begin(), shown.end(), layer->name()) != shown.end();
}

void LayerVisibility::setByUser(render::Layer& layer, bool visible) {
  layer.visible = visible;
  settled_.insert(layer.name());
}

void LayerVisibility::analysisArrived(const Layers& layers, const render::Analysis& analysis) {
  for (const auto& layer : layers) {
    const std::string name = layer->name();
    if (!render::needsAnalysis(name) || settled_.count(name) || !hasAnalysisData(name, analysis)) continue;
    layer->visible = true;
    settled_.insert(name);
  }
}

}  // namespace hdprior::ui
