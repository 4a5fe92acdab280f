#pragma once
#include <filesystem>
#include <future>
#include <utility>
#include <vector>
#include <memory>
#include <optional>
#include <string>

#include "engine/changes/map_change_report.h"
#include "engine/match/cost_landscape.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/keyframe_inspection.h"
#include "render/analysis.h"
#include "ui/comparison_runner.h"
#include "ui/match_history.h"
#include "ui/odometry_file.h"
#include "ui/session_runner.h"

namespace hdprior::ui {

// The tuning and debugging bench of the open log: the configuration being tuned, the pipeline
// session (run in the background by the SessionRunner), the selected keyframe with its re-computed
// match and cost landscape, and the render::Analysis the layers draw. Every number comes from the
// engine code the CLI runs.
class TuningBench {
 public:
  TuningBench(const ArgoverseLog& log, const Config& config);

  Config config;  // the next run, match and optimisation use it
  std::filesystem::path configPath = "hdprior.json";
  std::filesystem::path exportDir = "hdprior-export";
  CostLandscapeOptions landscapeOptions;
  bool landscapeEnabled = true;

  // A trajectory file opened as the odometry: drawn as the file_trajectory layer, plotted, and taken
  // by the next run, step or reset while its `use` is on.
  OdometryFile odometryFile;
  // Opens odometryFile with its fields (false: its error() says why) / closes it; the analysis follows.
  bool openOdometryFile();
  bool openOdometryFile(GivenOdometry given);
  void closeOdometryFile();
  // What a new session runs with: the odometry file when opened and used (run --odometry).
  PipelineOptions pipelineOptions() const;

  SessionRunner& runner() { return runner_; }
  // Once a UI frame; true when the analysis changed (a job ended, a keyframe was matched).
  bool poll();

  void run();           // a new session with `config`, to the end, optimised
  void stepKeyframe();  // the current session (or a new one) to its next keyframe, then inspects it
  void optimize();      // the graph with config.prior and config.graph
  void reset();         // drops the session: the next job starts a new one with config and pipelineOptions()
  // Selects keyframe k and matches it with config (road points, match options) from the pose the
  // run started its match from, offset by `startOffset` (dx forward, dy left, dyaw; its frame).
  void selectKeyframe(size_t k);
  void matchSelected();
  // Every re-match with its parameters; restoring a row takes its parameters and re-matches its keyframe.
  MatchHistory history;
  void restoreHistory(size_t row);
  Eigen::Vector3d startOffset = Eigen::Vector3d::Zero();

  std::optional<size_t> selected() const { return selected_; }
  const std::optional<KeyframeInspection>& inspection() const { return analysis_.inspection; }
  const render::Analysis& analysis() const { return analysis_; }
  // Shows an analysis computed elsewhere (a run read back, a benchmark's synthetic one) until the
  // next job ends.
  void showAnalysis(render::Analysis analysis);
  // The keyframe nearest in time to a frame, when the session has keyframes.
  std::optional<size_t> keyframeAtFrame(size_t frame);
  size_t keyframeCount();
  std::string message;  // the last error of a match or config file, shown in the panels
  double matchMs = 0.0;      // the last re-match: road points and match
  double landscapeMs = 0.0;  // the last cost landscape (on its own worker)
  bool landscapePending() const { return landscapeJob_.valid(); }
  // Blocks until the landscape of the last match is there (scripts, tests).
  void waitForLandscape();
  std::optional<size_t> frameToShow;  // set when a step made a keyframe: the app goes to its frame

  void saveConfig();
  void loadConfig();

  // The A/B comparison: run B over the same log with `b` (the bench's parameters or a file's), in
  // the background; its trajectory, diagnostics and its match of the selected keyframe join the
  // analysis when it ends. compareFile: false when the file is not a valid configuration (message says why).
  void compare(const Config& b, std::string name, std::optional<std::filesystem::path> file = std::nullopt);
  bool compareFile(const std::filesystem::path& file);
  void clearComparison();
  ComparisonRunner& comparison() { return comparison_; }
  // The user's measurement (none: cleared), drawn by the measure layer.
  void setMeasure(std::optional<GroundMeasure> measure);
  // The map check (hdprior changes) along the run's final trajectory, in the background; when it
  // ends its report joins the analysis (the changes layer, map-change events) until the next run.
  // False (message says why) without a finished run.
  bool checkMap();
  bool mapCheckPending() const { return mapCheckJob_.valid(); }
  void waitForMapCheck();  // blocks until the map check has joined the analysis (scripts, tests)
  // Run A's figures for the comparison table, once its run has ended.
  const std::optional<RunSummary>& summary() const { return summary_; }

 private:
  struct LandscapeInput {
    const HdMap* map = nullptr;
    std::vector<Eigen::Vector2d> points;
    Eigen::Vector3d center;
    MatchOptions match;
  };
  struct LandscapeRequest {
    LandscapeInput a;
    std::optional<LandscapeInput> b;  // run B's match of the same keyframe
    CostLandscapeOptions options;
    size_t generation = 0;
  };
  struct LandscapeResult {
    CostLandscape a;
    std::optional<CostLandscape> b;
    double ms = 0.0;  // A's
  };
  void refresh();
  void showComparison();
  std::optional<LandscapeInput> matchComparison(size_t keyframeA);
  void showOdometryFile();
  void requestLandscape(LandscapeRequest request);
  void pollLandscape();
  void pollMapCheck();

  const ArgoverseLog& log_;
  SessionRunner runner_;
  ComparisonRunner comparison_;
  std::optional<RunSummary> summary_;
  std::optional<size_t> selected_;
  render::Analysis analysis_;
  bool changed_ = false;
  bool selectNewest_ = false;
  // Declared after runner_: destroyed (waited for) before the map it reads.
  std::future<LandscapeResult> landscapeJob_;
  std::future<MapChangeReport> mapCheckJob_;
  std::optional<LandscapeRequest> pendingLandscape_;
  size_t landscapeGeneration_ = 0, landscapeJobGeneration_ = 0;
};

// What the bench shows, as text lines (`report` in view scripts): the session, the inspected
// keyframe's match and its error against the truth, the last solve, the ATE.
std::string benchReport(TuningBench& bench);

// Where the session's odometry comes from: "built-in lidar odometry" or "file F (tum, frame first)".
std::string odometrySourceText(const Session& session);

// The keyframe of a session nearest in time to a log frame; nullopt without keyframes.
std::optional<size_t> keyframeNearFrame(const Session& session, size_t frame);

// The RMSE of the finite values (per-pose errors are NaN where there is no ground truth); NaN if none.
double finiteRmse(const std::vector<double>& errors);

}  // namespace hdprior::ui
