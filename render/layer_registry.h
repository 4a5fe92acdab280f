#pragma once
#include <memory>
#include <string>
#include <vector>

#include "render/layer.h"

namespace hdprior::render {

// All layer names, in drawing order (bottom first).
const std::vector<std::string>& layerNames();
// The layers "all" means: every layer but the extras (crossings, accumulated), which the app
// shows and snapshots draw when named.
const std::vector<std::string>& standardLayerNames();
// The layers that draw the pipeline's results (render::Analysis): a snapshot naming one runs the pipeline.
bool needsAnalysis(const std::string& name);
// Throws Error("layer NAME", ...) for an unknown name.
std::unique_ptr<Layer> makeLayer(const std::string& name);
// Parses "a,b,c" (or "all", the standard layers); unknown names throw; the result is in drawing order.
std::vector<std::string> parseLayerList(const std::string& list);

}  // namespace hdprior::render
