#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/common_options.h"
#include "engine/error.h"
#include "engine/eval/eval_report.h"
#include "engine/io/file_bytes.h"
#include "engine/io/log_discovery.h"
#include "engine/pipeline/log_run.h"
#include "render/png_writer.h"

namespace hdprior::app {
namespace {

namespace fs = std::filesystem;

constexpr double kNoTimeBudgetMs = 1e6;  // the largest the configuration accepts

struct Batch {
  std::vector<fs::path> logs;
  Config config;
  PipelineOptions options;
  fs::path out;
  std::optional<fs::path> odometryDir;  // --odometry-dir: each log's trajectory file
  OdometryFileOptions odometryFile;
};

// D/<log id>.tum or D/<log id>.txt; a log with neither (or both) is that log's error.
fs::path logTrajectoryFile(const fs::path& dir, const std::string& id) {
  const fs::path tum = dir / (id + ".tum"), txt = dir / (id + ".txt");
  const bool hasTum = fs::exists(tum), hasTxt = fs::exists(txt);
  if (hasTum && hasTxt) throw Error(tum.string(), "and " + txt.string() + " both exist: which is the log's odometry?");
  if (!hasTum && !hasTxt) throw Error(tum.string(), "no trajectory for this log (--odometry-dir needs <log id>.tum or <log id>.txt)");
  return hasTum ? tum : txt;
}

// Output folders are named by log id, so two logs with one id would overwrite each other.
void requireUniqueIds(const std::vector<fs::path>& logs) {
  std::map<std::string, fs::path> seen;
  for (const fs::path& log : logs) {
    const auto [it, fresh] = seen.emplace(log.filename().string(), log);
    if (!fresh) throw Error(log.string(), "has the same log id as " + it->second.string());
  }
}

LogEvaluation evaluateLog(const Batch& batch, const fs::path& dir) {
  try {
    const ArgoverseLog log(dir);
    PipelineOptions options = batch.options;
    if (batch.odometryDir) options.givenOdometry = givenOdometryOf(logTrajectoryFile(*batch.odometryDir, log.id()), batch.odometryFile, log);
    return logEvaluation(log, runAndWriteLog(log, batch.config, options, batch.out / log.id()));
  } catch (const Error& e) {
    LogEvaluation failed;
    failed.id = dir.filename().string();
    failed.path = dir;
    failed.error = e.what();
    return failed;
  }
}

std::string progressLine(const LogEvaluation& e, double seconds) {
  char b[256];
  if (!e.ok()) {
    std::snprintf(b, sizeof b, "%s: failed (below), %.0f s", e.id.c_str(), seconds);
  } else if (e.optimized) {
    std::snprintf(b, sizeof b, "%s: odometry rmse %.3f m, optimized %.3f m, %.0f s", e.id.c_str(),
                  e.odometry->ate.translation.rmse, e.optimized->ate.translation.rmse, seconds);
  } else {
    std::snprintf(b, sizeof b, "%s: odometry rmse %.3f m, %.0f s", e.id.c_str(), e.odometry->ate.translation.rmse, seconds);
  }
  return b;
}

// One log per worker: each takes the next index from a shared counter and stores its result at that
// index, so the results' order never depends on timing. An Error fails only its log; anything else
// stops the batch and is rethrown here.
std::vector<LogEvaluation> evaluateLogs(const Batch& batch, size_t jobs) {
  std::vector<LogEvaluation> results(batch.logs.size());
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  size_t finished = 0;
  std::exception_ptr unexpected;
  auto worker = [&] {
    for (size_t i = next++; i < batch.logs.size() && !stop; i = next++) {
      try {
        const auto start = std::chrono::steady_clock::now();
        results[i] = evaluateLog(batch, batch.logs[i]);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::lock_guard lock(mutex);
        for (const std::string& skipped : results[i].skippedSweeps) {
          std::fprintf(stderr, "hdprior eval: log %s: warning: skipped %s\n", results[i].id.c_str(), skipped.c_str());
        }
        std::fprintf(stderr, "[%zu/%zu] %s\n", ++finished, batch.logs.size(), progressLine(results[i], seconds).c_str());
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!unexpected) unexpected = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (size_t w = 1; w < std::min(jobs, batch.logs.size()); ++w) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (unexpected) std::rethrow_exception(unexpected);
  return results;
}

render::Image rgba(const RgbImage& im) {
  render::Image out{im.width, im.height, std::vector<uint8_t>(size_t(im.width) * size_t(im.height) * 4, 255)};
  for (size_t p = 0; p < size_t(im.width) * size_t(im.height); ++p) {
    for (size_t c = 0; c < 3; ++c) out.rgba[p * 4 + c] = im.rgb[p * 3 + c];
  }
  return out;
}

}  // namespace

int runEval(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"out", "config", "jobs", "odometry-drift", "odometry-dir", "odometry-format", "odometry-frame"},
                              .flags = {"no-prior", "keep-time-budget"},
                              .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior eval DIR --out OUTDIR [-j N] [--config FILE] [--no-prior] [--keep-time-budget] "
                                       "[--odometry-drift SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M]] [--odometry-dir D "
                                       "[--odometry-format tum|kitti] [--odometry-frame first|city]]",
                              .shortNames = {{'j', "jobs"}}});
  Batch batch;
  batch.out = outputFolder(cl.required("out"));
  const long long jobs = cl.integer("jobs", std::max(1u, std::thread::hardware_concurrency()));
  if (jobs < 1) throw Error("option --jobs", "must be at least 1");
  batch.config = configOption(cl);
  // The matcher's wall-clock budget rejects matches that run long on a loaded machine, which would
  // make a log's result depend on the number of workers and whatever else runs.
  if (!cl.has("keep-time-budget")) batch.config.match.timeBudgetMs = kNoTimeBudgetMs;
  batch.options.priors = !cl.has("no-prior");
  batch.odometryFile = odometryFileOptions(cl, "odometry-dir");
  if (const auto d = cl.value("odometry-dir")) {
    if (!fs::is_directory(*d)) throw Error("option --odometry-dir", "'" + *d + "' is not a folder");
    batch.odometryDir = *d;
  }
  const fs::path dir = cl.positional()[0];
  batch.logs = findArgoverseLogs(dir);
  if (batch.logs.empty()) throw Error(dir.string(), "no Argoverse 2 logs under it");
  requireUniqueIds(batch.logs);
  fs::create_directories(batch.out);

  const std::vector<LogEvaluation> results = evaluateLogs(batch, size_t(jobs));
  const EvalSummary summary = summarizeLogs(results);
  writeFileAtomically(batch.out / "per_log.csv", perLogCsv(results));
  writeFileAtomically(batch.out / "table.md", summaryMarkdown(summary));
  writeFileAtomically(batch.out / "table.csv", summaryCsv(summary));
  render::writePng(batch.out / "rmse_boxplot.png", rgba(rmseBoxPlot(results)));

  std::printf("%s\nwrote %s (per_log.csv, table.md, table.csv, rmse_boxplot.png, a folder per log)\n",
              summaryMarkdown(summary).c_str(), batch.out.string().c_str());
  for (const LogEvaluation& e : results) {
    if (!e.ok()) std::fprintf(stderr, "hdprior eval: log %s: %s\n", e.id.c_str(), e.error.c_str());
  }
  return summary.failed ? 2 : 0;
}

}  // namespace hdprior::app
