#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "engine/pipeline/config.h"
#include "engine/pipeline/run_summary.h"
#include "ui/session_runner.h"

namespace hdprior::ui {

// Run B of the bench's A/B comparison: the same log with another configuration (the bench's
// current parameters or a config file), run to the end and optimised in the background by its own
// SessionRunner, exactly as `hdprior run --config` runs it.
class ComparisonRunner {
 public:
  explicit ComparisonRunner(const ArgoverseLog& log) : log_(log) {}

  // Starts B (ignored while B runs). `name` labels it: the file's name or "bench parameters";
  // `file` is the configuration file it came from, if any (kept in sessions).
  void start(const Config& config, const PipelineOptions& options, std::string name,
             std::optional<std::filesystem::path> file = std::nullopt);
  void clear();  // no B: the view shows A alone
  bool busy() const { return runner_ && runner_->busy(); }
  float progress() const { return runner_ ? runner_->progress() : 0.0f; }
  // Once a UI frame: true when B's run ended since the last call (error() says if it failed).
  bool poll();
  void wait();
  const std::string& error() const { return error_; }

  bool active() const { return runner_ != nullptr; }
  const std::string& name() const { return name_; }
  const Config& config() const { return config_; }
  const std::optional<std::filesystem::path>& file() const { return file_; }
  const std::optional<RunSummary>& summary() const { return summary_; }
  // B's finished session and its map; nullptr while it runs or before.
  Session* session() { return runner_ ? runner_->session() : nullptr; }
  const HdMap* map() const { return runner_ ? runner_->map() : nullptr; }

 private:
  const ArgoverseLog& log_;
  std::unique_ptr<SessionRunner> runner_;
  std::string name_, error_;
  Config config_;
  std::optional<std::filesystem::path> file_;
  std::optional<RunSummary> summary_;
};

}  // namespace hdprior::ui
