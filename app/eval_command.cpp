#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/eval_logs.h"
#include "app/eval_merge.h"
#include "app/option_checks.h"
#include "engine/changes/change_report_files.h"
#include "engine/changes/map_change_report.h"
#include "engine/error.h"
#include "engine/eval/change_scoring.h"
#include "engine/eval/eval_shard.h"
#include "engine/eval/log_evaluation_file.h"
#include "engine/io/file_bytes.h"
#include "engine/io/log_map_files.h"
#include "engine/io/partial_folder.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/log_run.h"

namespace hdprior::app {
namespace {

namespace fs = std::filesystem;

constexpr double kNoTimeBudgetMs = 1e6;  // the largest the configuration accepts

struct Batch {
  std::vector<fs::path> logs;  // this shard's
  Config config;
  PipelineOptions options;
  fs::path out;
  std::optional<fs::path> odometryDir;  // --odometry-dir: each log's trajectory file
  OdometryFileOptions odometryFile;
  bool skipExisting = false;
  bool checkMap = false;  // --check-map
};

// D/<log id>.tum or D/<log id>.txt; a log with neither (or both) is that log's error.
fs::path logTrajectoryFile(const fs::path& dir, const std::string& id) {
  const fs::path tum = dir / (id + ".tum"), txt = dir / (id + ".txt");
  const bool hasTum = fs::exists(tum), hasTxt = fs::exists(txt);
  if (hasTum && hasTxt) throw Error(tum.string(), "and " + txt.string() + " both exist: which is the log's odometry?");
  if (!hasTum && !hasTxt) throw Error(tum.string(), "no trajectory for this log (--odometry-dir needs <log id>.tum or <log id>.txt)");
  return hasTum ? tum : txt;
}

// The map check along the run's final poses into `dir` (as `hdprior changes` writes it), scored
// against the log's map_change.json when it has one.
LogEvaluation::MapCheck checkMap(const ArgoverseLog& log, const PoseTrajectory& poses, const Config& config, const fs::path& dir) {
  const std::unique_ptr<HdMap> map = loadCheckedMap(log, poses, config.roadPoints, ChangeOptions{});
  const MapChangeReport report = detectMapChanges(log, *map, poses, config.roadPoints, ChangeOptions{});
  writeChangeReport(dir, report, log.id());
  const std::optional<std::vector<MapChangeLabel>> labels = logMapChangeLabels(log.dir());
  const MapCheckScore score = scoreMapCheck(report, labels.value_or(std::vector<MapChangeLabel>{}));
  if (labels) writeFileAtomically(dir / "score.json", changeScoreJson(score));
  return {score.drivableAreas, score.crossings, score.laneLines, labels.has_value()};
}

// The log run into a temporary folder that replaces OUT/<log id> when complete.
LogEvaluation evaluateLog(const Batch& batch, const fs::path& dir) {
  try {
    const ArgoverseLog log(dir);
    PipelineOptions options = batch.options;
    if (batch.odometryDir) options.givenOdometry = givenOdometryOf(logTrajectoryFile(*batch.odometryDir, log.id()), batch.odometryFile, log);
    PartialFolder folder(batch.out / log.id());
    const EvaluatedRun run = runAndWriteLog(log, batch.config, options, folder.path());
    LogEvaluation e = logEvaluation(log, run);
    if (batch.checkMap) e.mapCheck = checkMap(log, run.run.final(), batch.config, folder.path() / "changes");
    fs::remove(logEvaluationFile(batch.out, log.id()));  // it describes the folder about to be replaced
    folder.publish();
    return e;
  } catch (const Error& e) {
    LogEvaluation failed;
    failed.id = logIdOfFolder(dir);
    failed.path = dir;
    failed.error = e.what();
    return failed;
  }
}

// The result file comes last, so it always describes the run folder beside it; a failed log
// leaves no run folder (one from an earlier run is removed).
void storeResult(const fs::path& out, const LogEvaluation& e) {
  if (!e.ok()) fs::remove_all(out / e.id);
  writeLogEvaluation(logEvaluationFile(out, e.id), e);
}

// --skip-existing: the stored result of a log that went through before, if any. A result file
// that cannot be read counts as missing: the log runs again and replaces it.
std::optional<LogEvaluation> storedSuccess(const fs::path& out, const fs::path& dir) {
  const std::string id = logIdOfFolder(dir);
  const fs::path file = logEvaluationFile(out, id);
  if (!fs::exists(file) || !fs::is_directory(out / id)) return std::nullopt;
  try {
    LogEvaluation e = readLogEvaluation(file);
    if (e.ok() && e.id == id) return e;
  } catch (const Error&) {
  }
  return std::nullopt;
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
        const std::optional<LogEvaluation> stored = batch.skipExisting ? storedSuccess(batch.out, batch.logs[i]) : std::nullopt;
        if (stored) {
          results[i] = *stored;
        } else {
          results[i] = evaluateLog(batch, batch.logs[i]);
          storeResult(batch.out, results[i]);
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::lock_guard lock(mutex);
        if (stored) {
          std::fprintf(stderr, "[%zu/%zu] %s: went through before, kept (--skip-existing)\n", ++finished, batch.logs.size(),
                       stored->id.c_str());
          continue;
        }
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

// A shard reports its own logs; the tables come from `merge` once every shard is done.
int reportShard(const Batch& batch, EvalShard shard, const fs::path& dir, const std::vector<LogEvaluation>& results) {
  size_t failed = 0;
  for (const LogEvaluation& e : results) {
    if (e.ok()) continue;
    ++failed;
    std::fprintf(stderr, "hdprior eval: log %s: %s\n", e.id.c_str(), e.error.c_str());
  }
  std::printf("shard %zu/%zu: %zu %s, %zu failed; each log's result in %s; when every shard is done: hdprior merge %s --logs %s\n",
              shard.index, shard.count, results.size(), results.size() == 1 ? "log" : "logs", failed, batch.out.string().c_str(),
              batch.out.string().c_str(), dir.string().c_str());
  return failed ? 2 : 0;
}

struct EvalArguments {
  std::string dir, out, shard, odometryDir;
  long long jobs = std::max(1u, std::thread::hardware_concurrency());
  bool skipExisting = false, noPrior = false, keepTimeBudget = false, checkMap = false;
  ConfigArguments config;
  OdometryFileArguments odometryFile;
};

int runEval(const EvalArguments& a) {
  Batch batch;
  batch.out = outputFolder(a.out);
  const std::optional<EvalShard> shard = a.shard.empty() ? std::nullopt : std::optional(parseEvalShard(a.shard));
  batch.skipExisting = a.skipExisting;
  batch.checkMap = a.checkMap;
  batch.config = configOf(a.config);
  // The matcher's wall-clock budget rejects matches that run long on a loaded machine, which would
  // make a log's result depend on the number of workers and whatever else runs.
  if (!a.keepTimeBudget) batch.config.match.timeBudgetMs = kNoTimeBudgetMs;
  batch.options.priors = !a.noPrior;
  batch.odometryFile = odometryFileOptions(a.odometryFile);
  if (!a.odometryDir.empty()) {
    if (!fs::is_directory(a.odometryDir)) throw Error("option --odometry-dir", "'" + a.odometryDir + "' is not a folder");
    batch.odometryDir = a.odometryDir;
  }
  const fs::path dir = a.dir;
  const std::vector<fs::path> logs = evalLogs(dir);
  batch.logs = logsOfShard(logs, shard.value_or(EvalShard{}));
  fs::create_directories(batch.out);

  // A plain eval is the one shard of all the logs, then the merge.
  const std::vector<LogEvaluation> results = evaluateLogs(batch, size_t(a.jobs));
  if (shard) return reportShard(batch, *shard, dir, results);
  return mergeEvaluation(batch.out, logs, "eval");
}

}  // namespace

Command addEvalCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "eval", "every Argoverse 2 log under DIR (or shard I of N of them), N at a time, each as `run` does into OUTDIR/<log id>/, "
              "then the paper's table over them (as `merge` does)");
  auto a = std::make_shared<EvalArguments>();
  command->add_option("DIR", a->dir, "the folder searched recursively for logs")->required();
  command->add_option("--out", a->out, "the output folder")->type_name("OUTDIR")->required();
  command->add_option("-j,--jobs", a->jobs, "logs run at a time (default: the number of cores)")->type_name("N")->check(integerAtLeast(1));
  command->add_option("--shard", a->shard, "only the logs k with k mod N = I (0-based), and no merge: a task of a job array")
      ->type_name("I/N")
      ->check(parsedBy([](const std::string& text) { parseEvalShard(text); }));
  command->add_flag("--skip-existing", a->skipExisting, "keep each log whose stored result says it went through");
  command->add_flag("--check-map", a->checkMap,
                    "also the map check (hdprior changes) of each log along its final poses, into OUTDIR/<log id>/changes; "
                    "the table adds its recall and precision against map_change.json, or its false alarms per km");
  addConfigOption(*command, a->config);
  command->add_flag("--no-prior", a->noPrior, "odometry only: no HD-map priors, no pose graph");
  command->add_flag("--keep-time-budget", a->keepTimeBudget,
                    "keep the matcher's wall-clock budget (off by default: results would depend on the machine's load)");
  addOdometryDriftOption(*command, a->config);
  CLI::Option* odometryDir =
      command->add_option("--odometry-dir", a->odometryDir, "each log's odometry from D/<log id>.tum or D/<log id>.txt")->type_name("D");
  addOdometryFileOptions(*command, a->odometryFile, odometryDir);
  return {command, [a] { return runEval(*a); }};
}

}  // namespace hdprior::app
