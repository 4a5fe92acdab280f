#pragma once
#include <filesystem>
#include <functional>

#include "engine/eval/eval_summary.h"
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/pipeline_run.h"

namespace hdprior {

struct EvaluatedRun {
  PipelineRun run;
  RunMetrics metrics;
};

// One log as `hdprior run` does it: the pipeline, its evaluation, and outDir's files
// (writeRunOutputs). Throws Error as runPipeline and writeRunOutputs do.
EvaluatedRun runAndWriteLog(const ArgoverseLog& log, const Config& config, const PipelineOptions& options,
                            const std::filesystem::path& outDir, const std::function<void(size_t, size_t)>& progress = {});

// The run's row of a batch evaluation.
LogEvaluation logEvaluation(const ArgoverseLog& log, const EvaluatedRun& r);

}  // namespace hdprior
