#include "ui/tuning_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "engine/error.h"
#include "engine/eval/change_scoring.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/odom/odometry.h"
#include "ui/ate_series.h"

namespace hdprior::ui {

namespace {

std::string sessionReport(TuningBench& bench, const Session* session) {
  if (!session) return "bench: no session\n";
  std::string out;
  char line[320];
  std::snprintf(line, sizeof line, "bench: sweeps %zu/%zu keyframes %zu\n", session->sweepsDone(), session->sweepCount(),
                session->odometry().keyframes().size());
  out += line;
  for (const SkippedSweep& s : session->skippedSweeps()) out += "bench: skipped " + s.file.string() + ": " + s.problem + "\n";
  if (!session->matches().empty()) out += "priors: " + constraintSummary(constraintsOf(session->matches())) + "\n";
  if (const auto& in = bench.inspection()) {
    const MatchResult& r = in->match;
    const double deg = 180.0 / M_PI;
    std::snprintf(line, sizeof line,
                  "match: keyframe %zu frame %zu status %s start %.4f %.4f %.4f estimate %.4f %.4f %.4f score %.2f "
                  "iterations %d path %zu\n",
                  in->keyframe, in->frame, toString(r.status), in->start.x(), in->start.y(), in->start.z() * deg,
                  r.estimate.x(), r.estimate.y(), r.estimate.z() * deg, r.score, r.iterations, r.path.size());
    out += line;
    out += "match constrains: " + constraintOf(r).label() + "\n";
    if (in->truth) {
      const Eigen::Vector3d e = planarError(*in->truth, r.estimate);
      std::snprintf(line, sizeof line, "match error: along %.4f lateral %.4f yaw_deg %.4f\n", e.x(), e.y(), e.z() * deg);
      out += line;
    }
  }
  if (const auto& l = bench.analysis().landscape) {
    const auto [lo, hi] = std::minmax_element(l->scores.begin(), l->scores.end());
    const auto [ylo, yhi] = std::minmax_element(l->yawScores.begin(), l->yawScores.end());
    const size_t best = size_t(hi - l->scores.begin());
    std::snprintf(line, sizeof line, "landscape: %dx%d score %.1f..%.1f max at offset %.2f %.2f; yaw %zu scores %.1f..%.1f\n",
                  l->size, l->size, *lo, *hi, l->offset(int(best % l->size)), l->offset(int(best / l->size)),
                  l->yawScores.size(), l->yawScores.empty() ? NAN : *ylo, l->yawScores.empty() ? NAN : *yhi);
    out += line;
  }
  if (const auto& s = bench.runner().lastSolve()) {
    std::snprintf(line, sizeof line, "solve: iterations %d cost %.6g -> %.6g\n", s->iterations, s->initialCost, s->finalCost);
    out += line;
    if (session->hasPriors()) {
      const PoseGraphOptions& g = session->graphOptions();
      std::snprintf(line, sizeof line, "drift model: %.4g m/m %.4g deg/m\n", g.odometryTranslationSigmaPerM, g.odometryRotationSigmaDegPerM);
      out += line;
    }
  }
  if (const auto& rows = bench.history.rows(); !rows.empty()) {
    std::string changes;
    for (const std::string& c : rows.back().changes) changes += (changes.empty() ? "" : "; ") + c;
    out += "history: " + std::to_string(rows.size()) + " rows, last: " + changes + " => " + rows.back().constraint + "\n";
  }
  out += "odometry: " + odometrySourceText(*session) + "\n";
  std::snprintf(line, sizeof line, "ate rmse: odometry %.4f optimized %.4f\n", finiteRmse(bench.analysis().odometryError),
                finiteRmse(bench.analysis().optimizedError));
  return out + line;
}

// The opened trajectory file and the ATE plot's lines.
std::string odometryFileReport(const TuningBench& bench) {
  std::string out;
  const render::Analysis& a = bench.analysis();
  if (const auto& given = bench.odometryFile.given()) {
    char line[320];
    std::snprintf(line, sizeof line, "odometry file: %s (%s, frame %s, %zu poses) %s, ate rmse %.4f\n", given->file.c_str(),
                  trajectoryFormatName(given->format), givenOdometryFrameName(given->frame), given->trajectory.size(),
                  bench.odometryFile.use ? "used by the next run" : "not used", finiteRmse(a.fileError));
    out += line;
  }
  out += "ate plot:";
  for (const AteSeries& s : ateSeries(a)) out += " [" + s.label + "]";
  return out + "\n";
}

// Run B against run A, when B has run.
std::string comparisonReport(TuningBench& bench) {
  const ComparisonRunner& b = bench.comparison();
  if (!b.summary()) return b.error().empty() ? "" : "compare: B failed: " + b.error() + "\n";
  char line[320];
  std::snprintf(line, sizeof line, "compare: A ate_rmse %.6f B ate_rmse %.6f\ncompare: B %s: %s\n",
                bench.summary() ? bench.summary()->ate.rmse : NAN, b.summary()->ate.rmse, b.name().c_str(),
                b.summary()->constraintSummary.c_str());
  return line;
}

// The map check's counts, when it has run.
std::string mapCheckReport(const render::Analysis& a) {
  if (!a.changes) return "";
  size_t contradicted = 0, consistent = 0;
  for (const DrivableAreaVerdict& v : a.changes->drivableAreas) {
    contradicted += v.verdict == MapVerdict::Contradicted;
    consistent += v.verdict == MapVerdict::Consistent;
  }
  size_t crossingsContradicted = 0, crossingsConsistent = 0;
  for (const CrossingVerdict& c : a.changes->crossings) {
    crossingsContradicted += c.verdict == MapVerdict::Contradicted;
    crossingsConsistent += c.verdict == MapVerdict::Consistent;
  }
  char line[300];
  std::snprintf(line, sizeof line,
                "map check: %zu drivable areas contradicted, %zu consistent, %zu missing surfaces, %.3f km of boundary observed; "
                "crossings: %zu contradicted, %zu consistent, %zu missing\n",
                contradicted, consistent, a.changes->missing.size(), a.changes->observedBoundaryKm, crossingsContradicted,
                crossingsConsistent, a.changes->missingCrossings.size());
  if (!a.changeLabels) return line;
  return line + ("against map_change.json: " + changeScoreLine(scoreMapCheck(*a.changes, *a.changeLabels)) + "\n");
}

}  // namespace

std::string benchReport(TuningBench& bench) {
  return sessionReport(bench, bench.runner().session()) + odometryFileReport(bench) + comparisonReport(bench) +
         mapCheckReport(bench.analysis());
}

std::string odometrySourceText(const Session& session) {
  const auto& given = session.givenOdometry();
  if (!given) return "built-in lidar odometry";
  return "file " + given->file + " (" + trajectoryFormatName(given->format) + ", frame " + givenOdometryFrameName(given->frame) + ")";
}

std::optional<size_t> keyframeNearFrame(const Session& session, size_t frame) {
  const auto& keyframes = session.odometry().keyframes();
  if (keyframes.empty()) return std::nullopt;
  const auto distance = [&](size_t k) {
    const size_t f = session.sweepOfFrame(keyframes[k].frame);
    return f > frame ? f - frame : frame - f;
  };
  size_t best = 0;
  for (size_t k = 1; k < keyframes.size(); ++k)
    if (distance(k) < distance(best)) best = k;
  return best;
}

double finiteRmse(const std::vector<double>& errors) {
  double sum = 0;
  size_t n = 0;
  for (double e : errors) {
    if (!std::isfinite(e)) continue;
    sum += e * e;
    ++n;
  }
  return n ? std::sqrt(sum / double(n)) : NAN;
}

TuningBench::TuningBench(const ArgoverseLog& log, const Config& config)
    : config(config), log_(log), runner_(log, config), comparison_(log) {}

bool TuningBench::openOdometryFile() {
  const bool opened = odometryFile.open(log_);
  showOdometryFile();
  return opened;
}

bool TuningBench::openOdometryFile(GivenOdometry given) {
  const bool opened = odometryFile.open(std::move(given), log_);
  showOdometryFile();
  return opened;
}

void TuningBench::closeOdometryFile() {
  odometryFile.close();
  showOdometryFile();
}

void TuningBench::showOdometryFile() {
  const auto& given = odometryFile.given();
  render::setFileTrajectory(analysis_, log_.cityTEgoAtSweeps(), odometryFile.cityTrajectory(), given ? given->file : "");
  changed_ = true;
}

PipelineOptions TuningBench::pipelineOptions() const {
  PipelineOptions options;
  options.givenOdometry = odometryFile.forRun();
  return options;
}

bool TuningBench::poll() {
  pollLandscape();
  pollMapCheck();
  if (comparison_.poll()) showComparison();
  if (runner_.poll()) {
    refresh();
    if (std::exchange(selectNewest_, false) && keyframeCount() > 0) selected_ = keyframeCount() - 1;
    if (selected_ && *selected_ < keyframeCount()) {
      matchSelected();
      if (analysis_.inspection) frameToShow = analysis_.inspection->frame;
    }
    changed_ = true;
  }
  return std::exchange(changed_, false);
}

void TuningBench::refresh() {
  const Session* session = runner_.session();
  if (!session) return;
  render::Analysis previous = std::move(analysis_);
  analysis_ = render::analysisOf(*session);
  analysis_.inspection = std::move(previous.inspection);
  analysis_.landscape = std::move(previous.landscape);
  analysis_.comparison = std::move(previous.comparison);
  analysis_.measure = previous.measure;
  if (previous.changes) render::setMapChanges(analysis_, previous.changes, std::move(previous.changeLabels), log_.sweepTimestamps());
  summary_.reset();
  if (session->done()) {
    try {
      summary_ = summarizeRun(*session);
    } catch (const Error& e) {
      message = e.what();
    }
  }
  showOdometryFile();
}

// The landscape takes a second or more (thousands of poses x thousands of points): it runs on its own
// worker while the match result shows at once. A request made while one runs waits for it; only the
// newest waiting request is kept.
void TuningBench::requestLandscape(LandscapeRequest request) {
  request.generation = ++landscapeGeneration_;
  if (landscapeJob_.valid()) {
    pendingLandscape_ = std::move(request);
    return;
  }
  landscapeJobGeneration_ = request.generation;
  landscapeJob_ = std::async(std::launch::async, [r = std::move(request)] {
    const auto t0 = std::chrono::steady_clock::now();
    LandscapeResult out;
    out.a = matchLandscape(*r.a.map, r.a.match, r.a.points, r.a.center, r.options);
    out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (r.b) out.b = matchLandscape(*r.b->map, r.b->match, r.b->points, r.b->center, r.options);
    return out;
  });
}

void TuningBench::pollLandscape() {
  if (!landscapeJob_.valid() || landscapeJob_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  LandscapeResult result = landscapeJob_.get();
  if (landscapeJobGeneration_ == landscapeGeneration_) {
    analysis_.landscape = std::move(result.a);
    if (analysis_.comparison) analysis_.comparison->landscape = std::move(result.b);
    landscapeMs = result.ms;
    changed_ = true;
  }
  if (pendingLandscape_) {
    LandscapeRequest next = std::move(*pendingLandscape_);
    pendingLandscape_.reset();
    --landscapeGeneration_;  // requestLandscape numbers it again
    requestLandscape(std::move(next));
  }
}

void TuningBench::waitForLandscape() {
  while (landscapeJob_.valid()) {
    landscapeJob_.wait();
    pollLandscape();
  }
}

void TuningBench::run() {
  if (runner_.busy()) return;
  mapCheckJob_ = {};  // waits for a map check of the old run, which reads the map a new run may replace
  runner_.restart(config, pipelineOptions());
  runner_.run();
  selected_.reset();
  render::Analysis previous = std::move(analysis_);
  analysis_ = {};
  analysis_.comparison = std::move(previous.comparison);
  if (analysis_.comparison) analysis_.comparison->inspection.reset(), analysis_.comparison->landscape.reset();
  analysis_.measure = previous.measure;
  summary_.reset();
  showOdometryFile();
  ++landscapeGeneration_;  // a landscape still being computed belongs to the old session
  changed_ = true;
}

bool TuningBench::checkMap() {
  const Session* session = runner_.session();
  if (runner_.busy() || mapCheckPending() || !session || !session->done() || !runner_.map()) {
    message = "the map check needs a finished run";
    return false;
  }
  const HdMap* map = runner_.map();
  auto job = [this, map, poses = render::finalTrajectory(analysis_), roadPoints = config.roadPoints] {
    return detectMapChanges(log_, *map, poses, roadPoints, ChangeOptions{});
  };
  mapCheckJob_ = std::async(std::launch::async, std::move(job));
  return true;
}

void TuningBench::pollMapCheck() {
  if (!mapCheckJob_.valid() || mapCheckJob_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  try {
    render::setMapChanges(analysis_, mapCheckJob_.get(), logMapChangeLabels(log_.dir()), log_.sweepTimestamps());
  } catch (const Error& e) {
    message = e.what();
  }
  changed_ = true;
}

void TuningBench::waitForMapCheck() {
  if (mapCheckJob_.valid()) mapCheckJob_.wait();
  pollMapCheck();
}

void TuningBench::stepKeyframe() {
  if (!runner_.session()) runner_.restart(config, pipelineOptions());
  runner_.stepKeyframe();
  selectNewest_ = true;
}

void TuningBench::optimize() { runner_.optimize(config.prior, config.graph); }

void TuningBench::reset() { runner_.restart(config, pipelineOptions()); }

size_t TuningBench::keyframeCount() {
  const Session* session = runner_.session();
  return session ? session->odometry().keyframes().size() : 0;
}

std::optional<size_t> TuningBench::keyframeAtFrame(size_t frame) {
  const Session* session = runner_.session();
  return session ? keyframeNearFrame(*session, frame) : std::nullopt;
}

void TuningBench::selectKeyframe(size_t k) {
  selected_ = k;
  matchSelected();
}

namespace {

// Where a keyframe's re-match starts: the run's prediction for it (the keyframe's pose without
// priors), moved by the tuning panel's offset; nullopt without an offset (the session's own start).
std::optional<Eigen::Vector3d> matchStart(const Session& session, size_t k, const Eigen::Vector3d& offset) {
  if (offset == Eigen::Vector3d::Zero()) return std::nullopt;
  const Eigen::Vector3d base = k < session.matches().size() ? planarPose(session.matches()[k].predicted)
                                                             : planarPose(session.keyframePoses().at(k));
  return offsetPose(base, offset);
}

}  // namespace

void TuningBench::matchSelected() {
  Session* session = runner_.session();
  const HdMap* map = runner_.map();
  if (!session || !map || !selected_) return;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const size_t k = *selected_;
    KeyframeInspection inspection = session->inspectKeyframe(k, config.roadPoints, config.match, matchStart(*session, k, startOffset));
    matchMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    history.add(config, startOffset, inspection);
    std::optional<LandscapeInput> b = matchComparison(k);
    if (!landscapeEnabled || inspection.roadPoints.empty()) analysis_.landscape.reset();
    else requestLandscape({{map, inspection.roadPoints, inspection.match.estimate, config.match}, std::move(b), landscapeOptions});
    analysis_.inspection = std::move(inspection);
    message.clear();
  } catch (const Error& e) {
    message = e.what();
  }
  changed_ = true;
}

// Run B's match of the keyframe nearest A's keyframe k, from the same offset; what its landscape needs.
std::optional<TuningBench::LandscapeInput> TuningBench::matchComparison(size_t keyframeA) {
  if (!analysis_.comparison) return std::nullopt;
  render::Comparison& b = *analysis_.comparison;
  b.inspection.reset();
  b.landscape.reset();
  Session* session = comparison_.session();
  const HdMap* map = comparison_.map();
  const Session* a = runner_.session();
  if (!session || !map || !a || !session->hasPriors()) return std::nullopt;
  const std::optional<size_t> k = keyframeNearFrame(*session, a->sweepOfFrame(a->odometry().keyframes().at(keyframeA).frame));
  if (!k) return std::nullopt;
  const Config& c = comparison_.config();
  try {
    b.inspection = session->inspectKeyframe(*k, c.roadPoints, c.match, matchStart(*session, *k, startOffset));
  } catch (const Error& e) {
    message = std::string("B: ") + e.what();
    return std::nullopt;
  }
  if (!landscapeEnabled || b.inspection->roadPoints.empty()) return std::nullopt;
  return LandscapeInput{map, b.inspection->roadPoints, b.inspection->match.estimate, c.match};
}

void TuningBench::compare(const Config& b, std::string name, std::optional<std::filesystem::path> file) {
  if (comparison_.busy()) return;
  analysis_.comparison.reset();
  comparison_.start(b, pipelineOptions(), std::move(name), std::move(file));
  changed_ = true;
}

bool TuningBench::compareFile(const std::filesystem::path& file) {
  try {
    compare(hdprior::loadConfig(file), file.filename().string(), file);
    message.clear();
    return true;
  } catch (const Error& e) {
    message = e.what();
    return false;
  }
}

void TuningBench::restoreHistory(size_t row) {
  if (row >= history.rows().size()) return;
  const MatchHistoryRow r = history.rows()[row];
  config = r.config;
  startOffset = r.startOffset;
  selectKeyframe(r.keyframe);
}

void TuningBench::showAnalysis(render::Analysis analysis) {
  analysis_ = std::move(analysis);
  changed_ = true;
}

void TuningBench::setMeasure(std::optional<GroundMeasure> measure) {
  analysis_.measure = measure;
  changed_ = true;
}

void TuningBench::clearComparison() {
  if (comparison_.busy()) return;
  comparison_.clear();
  analysis_.comparison.reset();
  changed_ = true;
}

void TuningBench::showComparison() {
  changed_ = true;
  Session* session = comparison_.session();
  if (!comparison_.error().empty() || !session) {
    message = comparison_.error();
    return;
  }
  analysis_.comparison = render::comparisonOf(*session, comparison_.name());
  if (selected_ && runner_.session()) matchSelected();
}

void TuningBench::saveConfig() {
  try {
    hdprior::saveConfig(configPath, config);
    message = "saved " + configPath.string();
  } catch (const Error& e) {
    message = e.what();
  }
}

void TuningBench::loadConfig() {
  try {
    config = hdprior::loadConfig(configPath);
    message = "loaded " + configPath.string();
  } catch (const Error& e) {
    message = e.what();
  }
}

}  // namespace hdprior::ui
