#pragma once
#include <atomic>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "engine/pipeline/config.h"
#include "engine/pipeline/session.h"

namespace hdprior {
class ArgoverseLog;
class HdMap;
}  // namespace hdprior

namespace hdprior::ui {

// The pipeline Session of the open log, driven from the UI without blocking it: each job (run to the
// end, step to the next keyframe, optimise) runs on a worker thread; the UI polls once a frame and
// reads the session only while no job runs. The first job loads the HD map the priors need (NDT grids
// of every size the tuning panel offers, the boundary distance field).
class SessionRunner {
 public:
  SessionRunner(const ArgoverseLog& log, const Config& config);
  ~SessionRunner();  // cancels a running job and waits for it

  bool busy() const { return job_.valid(); }
  const std::string& jobName() const { return jobName_; }
  float progress() const { return progress_.load(); }  // of the running job, 0..1

  // Each starts a job (ignored while one runs). restart() drops the session: the next job starts a
  // new one with `config` (the odometry, keyframe and road-point options take effect then) and
  // `options` (a given odometry: the run over a trajectory file, as `run --odometry`).
  void run();
  void stepKeyframe();
  void optimize(const PosePriorOptions& prior, const PoseGraphOptions& graph);
  void restart(const Config& config, const PipelineOptions& options = {});
  // The global map from the keyframe sweeps at the session's final poses, voxelised, to a PLY file.
  void exportMap(const std::filesystem::path& file, double voxel);
  void cancel() { cancel_ = true; }
  // Blocks until the running job ends (scripts, tests).
  void wait();

  // Once a UI frame: true when a job ended since the last call. A job that threw leaves its
  // message in error().
  bool poll();
  const std::string& error() const { return error_; }
  const std::string& lastJob() const { return lastJob_; }  // what the last finished job did, for the status line
  const std::optional<SolveSummary>& lastSolve() const { return lastSolve_; }
  double lastSolveMs() const { return lastSolveMs_; }

  // nullptr while a job runs or before the first one.
  Session* session() { return busy() ? nullptr : session_.get(); }
  const HdMap* map() const { return busy() ? nullptr : map_.get(); }

 private:
  void start(std::string name, std::function<void()> work);
  void ensureSession();

  const ArgoverseLog& log_;
  Config config_;
  PipelineOptions options_;
  std::unique_ptr<HdMap> map_;
  std::unique_ptr<Session> session_;
  std::future<void> job_;
  std::string jobName_, lastJob_, error_;
  std::atomic<float> progress_{0.0f};
  std::atomic<bool> cancel_{false};
  std::optional<SolveSummary> lastSolve_;
  double lastSolveMs_ = 0.0;
};

// The NDT cell sizes the app's map carries (the tuning panel's choices), plus the config's own.
std::vector<double> tuningCellSizes(const Config& config);

}  // namespace hdprior::ui
