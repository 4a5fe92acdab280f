#pragma once
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "render/analysis.h"
#include "render/layer.h"

namespace hdprior::ui {

// The layers the app shows at start: the log and its map without clutter.
const std::vector<std::string>& defaultVisibleLayers();
// Whether `analysis` holds what the analysis layer `name` draws.
bool hasAnalysisData(const std::string& name, const render::Analysis& analysis);

// Which layers the app shows: the default set at start, an analysis layer once its data first
// arrives, and from then on (or from the user's first toggle of it) whatever the user chose.
class LayerVisibility {
 public:
  using Layers = std::vector<std::unique_ptr<render::Layer>>;
  // Shows the default set, hides the rest, and forgets the user's choices.
  void reset(const Layers& layers);
  // The user showed or hid `layer`: arriving analysis data no longer changes it.
  void setByUser(render::Layer& layer, bool visible);
  // Shows each analysis layer whose data first arrived in `analysis`, unless the user chose first.
  void analysisArrived(const Layers& layers, const render::Analysis& analysis);

 private:
  std::set<std::string> settled_;  // toggled by the user, or already shown on arrival
};

}  // namespace hdprior::ui
