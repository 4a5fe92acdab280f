#include "app/eval_merge.h"

#include <cstdio>

#include "engine/error.h"
#include "engine/eval/eval_report.h"
#include "engine/eval/log_evaluation_file.h"
#include "engine/io/file_bytes.h"
#include "engine/io/log_map_files.h"
#include "render/png_writer.h"

namespace hdprior::app {
namespace {

namespace fs = std::filesystem;

LogEvaluation resultOf(const fs::path& out, const fs::path& log) {
  const std::string id = logIdOfFolder(log);
  const fs::path file = logEvaluationFile(out, id);
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    LogEvaluation missing;
    missing.id = id;
    missing.path = log;
    missing.error = "missing: no " + file.string() + " (its shard has not run, or stopped before this log)";
    return missing;
  }
  LogEvaluation e = readLogEvaluation(file);
  if (e.id != id) throw Error(file.string(), "holds the result of log '" + e.id + "', not of '" + id + "'");
  return e;
}

}  // namespace

int mergeEvaluation(const fs::path& out, const std::vector<fs::path>& logs, const std::string& command) {
  std::vector<LogEvaluation> results;
  for (const fs::path& log : logs) results.push_back(resultOf(out, log));
  const EvalSummary summary = summarizeLogs(results);
  const std::string table = summaryMarkdown(summary);
  writeFileAtomically(out / "per_log.csv", perLogCsv(results));
  writeFileAtomically(out / "table.md", table);
  writeFileAtomically(out / "table.csv", summaryCsv(summary));
  render::writePng(out / "rmse_boxplot.png", rmseBoxPlot(results));

  std::printf("%s\nwrote %s (per_log.csv, table.md, table.csv, rmse_boxplot.png, a folder per log)\n", table.c_str(),
              out.string().c_str());
  for (const LogEvaluation& e : results) {
    if (!e.ok()) std::fprintf(stderr, "hdprior %s: log %s: %s\n", command.c_str(), e.id.c_str(), e.error.c_str());
  }
  return summary.failed ? 2 : 0;
}

}  // namespace hdprior::app
