#include "engine/changes/surface_classes.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace hdprior {

namespace {

constexpr std::pair<int, int> kNeighbours[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// The surface a growth carries along: each accepted cell's reference is the mean of its own
// values and the reference of the cell it was reached from, so a slow grade or a fading
// brightness is followed while a kerb, a slope up onto a sidewalk or a brighter surface is not.
struct Reference {
  float height = 0, intensity = 0;
  Reference towards(const SurfaceCell& c) const { return {0.5f * (height + c.height()), 0.5f * (intensity + c.intensity())}; }
};

bool described(const SurfaceCell& c, const ChangeOptions& o) { return c.near >= o.surfaceMinPoints; }

bool sameSurface(const Reference& r, const SurfaceCell& c, const ChangeOptions& o) {
  if (std::abs(c.height() - r.height) >= o.surfaceStep) return false;
  const double i = c.intensity(), ri = r.intensity;
  return std::abs(i - ri) <= std::max(o.surfaceIntensityFloor, o.surfaceIntensityShare * std::max(i, ri));
}

// Cells the road walk reached on most of its visits: the growth's seeds.
bool walked(const SurfaceCell& c) { return c.road >= 3 && 5 * c.offRoad <= c.road; }

// Grows `label` from the queued cells over described cells that are still Unknown and of the
// same surface as the reference they are reached with, at most `steps` cells away; cells
// refused are handed to `refused`.
template <class Refused>
void grow(const SurfaceEvidence& evidence, std::vector<Surface>& surfaces, std::vector<Reference>& refs,
          std::deque<std::pair<size_t, int>> queue, Surface label, int steps, const ChangeOptions& o, Refused refused) {
  const GridGeometry& g = evidence.geometry();
  const std::vector<SurfaceCell>& cells = evidence.cells();
  while (!queue.empty()) {
    const auto [i, depth] = queue.front();
    queue.pop_front();
    if (depth >= steps) continue;
    const int c = int(i % size_t(g.cols)), r = int(i / size_t(g.cols));
    for (auto [dc, dr] : kNeighbours) {
      if (!g.inside(c + dc, r + dr)) continue;
      const size_t j = g.index(c + dc, r + dr);
      if (surfaces[j] != Surface::Unknown || !described(cells[j], o)) continue;
      if (sameSurface(refs[i], cells[j], o)) {
        surfaces[j] = label;
        refs[j] = refs[i].towards(cells[j]);
        queue.emplace_back(j, depth + 1);
      } else {
        refused(j);
      }
    }
  }
}

}  // namespace

void classifySurface(SurfaceEvidence& evidence, const ChangeOptions& options) {
  const std::vector<SurfaceCell>& cells = evidence.cells();
  std::vector<Surface> surfaces(cells.size(), Surface::Unknown);
  std::vector<Reference> refs(cells.size());
  std::deque<std::pair<size_t, int>> seeds;
  for (size_t i = 0; i < cells.size(); ++i)
    if (described(cells[i], options) && walked(cells[i])) {
      surfaces[i] = Surface::Road;
      refs[i] = {cells[i].height(), cells[i].intensity()};
      seeds.emplace_back(i, 0);
    }
  std::vector<size_t> edge;
  grow(evidence, surfaces, refs, std::move(seeds), Surface::Road, 1 << 30, options, [&](size_t j) { edge.push_back(j); });
  // What the road's growth refused, and the same surface a little beyond, is what lies beside the road.
  std::deque<std::pair<size_t, int>> beside;
  std::sort(edge.begin(), edge.end());
  edge.erase(std::unique(edge.begin(), edge.end()), edge.end());
  for (size_t j : edge)
    if (surfaces[j] == Surface::Unknown) {
      surfaces[j] = Surface::NotRoad;
      refs[j] = {cells[j].height(), cells[j].intensity()};
      beside.emplace_back(j, 0);
    }
  const int besideSteps = int(std::lround(options.reach / evidence.geometry().resolution));
  grow(evidence, surfaces, refs, std::move(beside), Surface::NotRoad, besideSteps, options, [](size_t) {});
  evidence.setSurfaces(std::move(surfaces));
}

}  // namespace hdprior
