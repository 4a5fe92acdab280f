#include "ui/session_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/ply_writer.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/global_map.h"

namespace hdprior::ui {

std::vector<double> tuningCellSizes(const Config& config) {
  std::vector<double> sizes = {0.5, 1.0, 2.0, 4.0, 8.0};
  for (double s : config.match.cellSizes) {
    if (std::find(sizes.begin(), sizes.end(), s) == sizes.end()) sizes.push_back(s);
  }
  std::sort(sizes.begin(), sizes.end());
  return sizes;
}

SessionRunner::SessionRunner(const ArgoverseLog& log, const Config& config) : log_(log), config_(config) {}

SessionRunner::~SessionRunner() {
  cancel_ = true;
  if (job_.valid()) job_.wait();
}

void SessionRunner::start(std::string name, std::function<void()> work) {
  if (busy()) return;
  jobName_ = std::move(name);
  progress_ = 0.0f;
  cancel_ = false;
  error_.clear();
  job_ = std::async(std::launch::async, std::move(work));
}

// Runs on the worker: the map and the session are created by the first job that needs them.
void SessionRunner::ensureSession() {
  if (!map_) {
    Config mapConfig = config_;
    mapConfig.match.cellSizes = tuningCellSizes(config_);
    map_ = loadPriorMap(log_, mapConfig);
  }
  if (!session_) session_ = std::make_unique<Session>(log_, map_.get(), config_, options_);
}

void SessionRunner::run() {
  start("running the pipeline", [this] {
    ensureSession();
    const bool finished = session_->run([this](size_t done, size_t total) { progress_ = float(done) / float(total); }, &cancel_);
    if (!finished) {
      lastJob_ = "cancelled at sweep " + std::to_string(session_->sweepsDone());
      return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    lastSolve_ = session_->optimize();
    lastSolveMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    lastJob_ = "ran " + std::to_string(session_->sweepsDone()) + " sweeps, " +
               std::to_string(session_->odometry().keyframes().size()) + " keyframes";
    if (!session_->skippedSweeps().empty()) lastJob_ += ", " + std::to_string(session_->skippedSweeps().size()) + " unreadable sweeps skipped";
  });
}

void SessionRunner::stepKeyframe() {
  start("stepping to the next keyframe", [this] {
    ensureSession();
    session_->stepKeyframe();
    progress_ = 1.0f;
    lastJob_ = "keyframe " + std::to_string(session_->odometry().keyframes().size() - 1) + " at sweep " +
               std::to_string(session_->sweepsDone() - 1);
  });
}

void SessionRunner::optimize(const PosePriorOptions& prior, const PoseGraphOptions& graph) {
  start("optimising the pose graph", [this, prior, graph] {
    ensureSession();
    const auto t0 = std::chrono::steady_clock::now();
    lastSolve_ = session_->optimize(prior, graph);
    lastSolveMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    progress_ = 1.0f;
    lastJob_ = "optimised " + std::to_string(session_->keyframePoses().size()) + " keyframes";
  });
}

void SessionRunner::restart(const Config& config, const PipelineOptions& options) {
  if (busy()) return;
  config_ = config;
  options_ = options;
  session_.reset();
  lastSolve_.reset();
  lastJob_ = "session reset";
}

void SessionRunner::exportMap(const std::filesystem::path& file, double voxel) {
  start("writing the map", [this, file, voxel] {
    ensureSession();
    const PoseTrajectory optimized = session_->optimizedTrajectory();
    const GlobalMap map = buildGlobalMap([s = session_.get()](size_t f) { return s->frameSweep(f); }, session_->odometry(),
                                         optimized.empty() ? session_->odometryTrajectory() : optimized, voxel);
    writePly(file, map.points, map.intensity);
    progress_ = 1.0f;
    lastJob_ = "wrote " + file.string() + " (" + std::to_string(map.points.size()) + " points)";
  });
}

void SessionRunner::wait() {
  if (job_.valid()) job_.wait();
}

bool SessionRunner::poll() {
  if (!job_.valid() || job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  try {
    job_.get();
  } catch (const Error& e) {
    error_ = e.what();
    lastJob_ = jobName_ + " failed";
  } catch (const std::exception& e) {
    error_ = std::string("internal error: ") + e.what();
    lastJob_ = jobName_ + " failed";
  }
  jobName_.clear();
  return true;
}

}  // namespace hdprior::ui
