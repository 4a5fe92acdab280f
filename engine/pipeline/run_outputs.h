#pragma once
#include <filesystem>

#include "engine/io/argoverse_log.h"
#include "engine/pipeline/pipeline_run.h"

namespace hdprior {

// DIR/groundtruth.tum, odometry.tum, (with priors) optimized.tum, keyframes.json (with each match),
// metrics.json and map.ply, each written atomically.
void writeRunOutputs(const std::filesystem::path& dir, const ArgoverseLog& log, const PipelineRun& run,
                     const RunMetrics& metrics);

}  // namespace hdprior
