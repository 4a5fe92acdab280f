#include "ui/comparison_runner.h"

#include "engine/error.h"

namespace hdprior::ui {

void ComparisonRunner::start(const Config& config, const PipelineOptions& options, std::string name,
                             std::optional<std::filesystem::path> file) {
  if (busy()) return;
  config_ = config;
  name_ = std::move(name);
  file_ = std::move(file);
  summary_.reset();
  error_.clear();
  runner_ = std::make_unique<SessionRunner>(log_, config);
  runner_->restart(config, options);
  runner_->run();
}

void ComparisonRunner::clear() {
  runner_.reset();
  summary_.reset();
  error_.clear();
  name_.clear();
  file_.reset();
}

bool ComparisonRunner::poll() {
  if (!runner_ || !runner_->poll()) return false;
  error_ = runner_->error();
  if (error_.empty() && runner_->session()) {
    try {
      summary_ = summarizeRun(*runner_->session());
    } catch (const Error& e) {
      error_ = e.what();
    }
  }
  return true;
}

void ComparisonRunner::wait() {
  if (runner_) runner_->wait();
}

}  // namespace hdprior::ui
