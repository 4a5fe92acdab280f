#include "engine/pipeline/log_run.h"

#include "engine/pipeline/run_outputs.h"

namespace hdprior {

EvaluatedRun runAndWriteLog(const ArgoverseLog& log, const Config& config, const PipelineOptions& options,
                            const std::filesystem::path& outDir, const std::function<void(size_t, size_t)>& progress) {
  EvaluatedRun r{runPipeline(log, config, options, progress), {}};
  r.metrics = evaluateRun(r.run);
  writeRunOutputs(outDir, log, r.run, r.metrics);
  return r;
}

LogEvaluation logEvaluation(const ArgoverseLog& log, const EvaluatedRun& r) {
  LogEvaluation e;
  e.id = log.id();
  e.path = log.dir();
  e.sweeps = r.run.estimate.size();
  for (const SkippedSweep& s : r.run.skippedSweeps) e.skippedSweeps.push_back(s.file.string() + ": " + s.problem);
  e.odometry = r.metrics.odometry;
  e.optimized = r.metrics.optimized;
  e.matchesAccepted = r.metrics.matches.accepted;
  e.matchesDegenerate = r.metrics.matches.degenerate;
  e.matchesRejected = r.metrics.matches.rejected;
  e.priorErrors = r.metrics.priorErrors;
  e.pipelineSeconds = r.run.times.pipelineS;
  return e;
}

}  // namespace hdprior
