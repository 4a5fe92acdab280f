// The app's draw loop (`hdprior view`): FPS of one frame (events, input, panels, the 3-D view,
// ImGui, buffer swap) in a 1280x720 window with 500,000+ lidar points visible. Two cases: the
// app as it runs (the 3-D view is drawn again only when the camera, frame or a layer setting
// changed, else copied from the view cache), and every layer drawn every frame (as while the
// camera moves).
// NEEDS A DISPLAY: run under Xvfb, e.g. `xvfb-run -a -s "-screen 0 1280x800x24"
// build/tests/bench/view_bench`; without one it reports an error instead of a figure.
// The shared log has only two sweeps, so the bench writes a log beside the temporary folder
// with the same map and poses and 7 sweeps (the two real ones repeated along the trajectory),
// and shows frame 3 with 3 accumulated sweeps before and after it.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/lidar_sweep.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/session.h"
#include "render/layers/accumulated_sweeps_layer.h"
#include "ui/app_state.h"
#include "ui/match_history.h"
#include "ui/viewer.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

const fs::path kLog = fs::path(HDPRIOR_SHARED_DATA) / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede";

// The shared log's map, poses and calibration (linked) with `sweeps` sweeps 0.1 s apart.
fs::path makeBenchLog(int sweeps) {
  const fs::path dir = fs::temp_directory_path() / "hdprior_view_bench" / kLog.filename();
  fs::remove_all(dir);
  fs::create_directories(dir / "sensors" / "lidar");
  for (const char* entry : {"map", "calibration", "city_SE3_egovehicle.feather"})
    fs::create_symlink(fs::absolute(kLog / entry), dir / entry);
  const ArgoverseLog real(kLog);
  for (int i = 0; i < sweeps; ++i) {
    LidarSweep sweep = *real.sweep(size_t(i % 2));
    sweep.timestampNs = real.sweepTimestamps()[0] + int64_t(i) * 100'000'000;
    writeLidarSweep(dir / "sensors" / "lidar" / (std::to_string(sweep.timestampNs) + ".feather"), sweep);
  }
  return dir;
}

// 1280x720 without vsync on the bench log of 7 sweeps.
ui::ViewerOptions benchOptions() {
  ui::ViewerOptions options;
  options.log = makeBenchLog(7);
  options.width = 1280;
  options.height = 720;
  options.swapInterval = 0;
  return options;
}

// The viewer with its log loaded, or nullptr (and the benchmark skipped) without a display.
std::unique_ptr<ui::Viewer> openViewer(benchmark::State& state, const ui::ViewerOptions& options) {
  try {
    auto viewer = std::make_unique<ui::Viewer>(options);
    viewer->waitForLog();
    return viewer;
  } catch (const Error& e) {
    state.SkipWithError((std::string("needs a display, run under xvfb-run -a: ") + e.what()).c_str());
    return nullptr;
  }
}

enum class Motion { Still, Orbiting };

void viewBench(benchmark::State& state, bool topDown, bool cacheView, Motion motion = Motion::Still) {
  ui::ViewerOptions options = benchOptions();
  options.cacheView = cacheView;
  if (!cacheView) options.interactivePoints = 0;  // every point, every frame
  const std::unique_ptr<ui::Viewer> viewer = openViewer(state, options);
  if (!viewer) return;
  ui::AppState& app = viewer->state();
  auto* accumulated = dynamic_cast<render::AccumulatedSweepsLayer*>(app.layer("accumulated"));
  accumulated->visible = true;  // an extra, hidden at start
  accumulated->setWindow(3);
  app.goToFrame(3);
  app.renderer().rebuild(*accumulated);
  app.camera.topDown = topDown;
  for (int i = 0; i < 5; ++i) viewer->frame();  // panels laid out, caches warm
  for (auto _ : state) {
    if (motion == Motion::Orbiting) app.camera.orbit(2.0, 0.0);
    viewer->frame();
  }
  state.counters["points"] = double(app.renderer().pointsDrawn());
  state.counters["FPS"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_ViewDrawLoop1280x720Orbit(benchmark::State& state) { viewBench(state, false, true); }
void BM_ViewDrawLoop1280x720Top(benchmark::State& state) { viewBench(state, true, true); }
void BM_ViewFullRedraw1280x720Orbit(benchmark::State& state) { viewBench(state, false, false); }
// The camera turning every frame, as the app draws it: every layer again, lidar layers thinned
// to about 100,000 points (every 7th of 695,314) while it moves.
void BM_ViewCameraMoving1280x720Orbit(benchmark::State& state) { viewBench(state, false, true, Motion::Orbiting); }
void BM_ViewFullRedraw1280x720Top(benchmark::State& state) { viewBench(state, true, false); }

// A frame change: the current sweep (about 100,000 points) and one newly accumulated sweep
// coloured and uploaded, then drawn. Alternates between two frames.
void BM_ViewFrameChange(benchmark::State& state) {
  const std::unique_ptr<ui::Viewer> viewer = openViewer(state, benchOptions());
  if (!viewer) return;
  ui::AppState& app = viewer->state();
  for (int i = 0; i < 5; ++i) viewer->frame();
  long long frame = 3;
  for (auto _ : state) {
    app.goToFrame(frame);
    viewer->frame();
    frame = frame == 3 ? 4 : 3;
  }
}

BENCHMARK(BM_ViewDrawLoop1280x720Orbit)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ViewDrawLoop1280x720Top)->Unit(benchmark::kMillisecond)->UseRealTime();
// A full redraw takes several hundred ms on llvmpipe: a fixed count keeps the run short.
BENCHMARK(BM_ViewFullRedraw1280x720Orbit)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(6);
BENCHMARK(BM_ViewFullRedraw1280x720Top)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(6);
BENCHMARK(BM_ViewCameraMoving1280x720Orbit)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(BM_ViewFrameChange)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(6);

}  // namespace
}  // namespace hdprior

namespace hdprior {
namespace {

// The draw loop with four Diagnostics plots (score, sigma lateral, chi2 with its gate, lateral
// error) over a 600-keyframe run: synthetic diagnostics of 600 keyframes spread over the bench
// log's frames, every value finite, statuses cycling.
void BM_ViewDrawLoopFourPlots600Keyframes(benchmark::State& state) {
  const std::unique_ptr<ui::Viewer> viewer = openViewer(state, benchOptions());
  if (!viewer) return;
  ui::AppState& app = viewer->state();
  render::Analysis analysis;
  for (size_t k = 0; k < 600; ++k) {
    KeyframeDiagnostic d;
    d.keyframe = k;
    d.frame = k * app.frameCount() / 600;
    d.constraint.kind = k % 10 == 9 ? PriorConstraint::Kind::Rejected : PriorConstraint::Kind::Fixes;
    d.constraint.lateral = d.constraint.yaw = true;
    d.constraint.along = k % 3 == 0;
    for (size_t f = 0; f < kDiagnosticFields; ++f) d.values[f] = std::sin(0.05 * double(k) + double(f));
    analysis.diagnostics.push_back(d);
  }
  app.bench().showAnalysis(std::move(analysis));
  for (const char* plot : {"score", "sigma_lateral", "chi2", "error_lateral"}) app.setPlotShown(plot, true);
  for (int i = 0; i < 5; ++i) viewer->frame();
  for (auto _ : state) viewer->frame();
  state.counters["FPS"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ViewDrawLoopFourPlots600Keyframes)->Unit(benchmark::kMillisecond)->UseRealTime();

// The NDT tab's re-match of a keyframe, history row included: the keyframe's road points from its
// sub-map (the real sweep: 4,085 road points after thinning), the match, and the row with what
// changed since the last one (an outlier ratio toggled between two values, as a slider would).
// Arg 0: without the row, to show what the row costs. Needs no display.
void BM_RematchWithHistoryRow(benchmark::State& state) {
  const ArgoverseLog log(kLog);
  Config config = defaultConfig();
  const std::unique_ptr<HdMap> map = loadPriorMap(log, config);
  Session session(log, map.get(), config);
  session.run();
  ui::MatchHistory history;
  size_t roadPoints = 0;
  for (auto _ : state) {
    config.match.outlierRatio = config.match.outlierRatio == 0.55 ? 0.5 : 0.55;
    const KeyframeInspection k = session.inspectKeyframe(0, config.roadPoints, config.match, std::nullopt);
    if (state.range(0)) history.add(config, Eigen::Vector3d::Zero(), k);
    else history.clear();
    roadPoints = k.roadPoints.size();
  }
  state.counters["road_points"] = double(roadPoints);
}
BENCHMARK(BM_RematchWithHistoryRow)->Unit(benchmark::kMillisecond)->Iterations(40)->Arg(1)->Arg(0);

}  // namespace
}  // namespace hdprior
