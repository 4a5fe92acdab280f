#include "engine/changes/missing_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "engine/map/boundary_distance.h"
#include "engine/map/ground_height.h"

namespace hdprior {

namespace {

std::vector<std::vector<int>> components(const GridGeometry& g, const std::vector<uint8_t>& mask) {
  std::vector<std::vector<int>> out;
  std::vector<uint8_t> seen(mask.size(), 0);
  for (size_t start = 0; start < mask.size(); ++start) {
    if (!mask[start] || seen[start]) continue;
    std::vector<int> cells, stack = {int(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      cells.push_back(i);
      const int c = i % g.cols, r = i / g.cols;
      for (auto [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (!g.inside(c + dc, r + dr)) continue;
        const size_t j = g.index(c + dc, r + dr);
        if (mask[j] && !seen[j]) seen[j] = 1, stack.push_back(int(j));
      }
    }
    std::sort(cells.begin(), cells.end());
    out.push_back(std::move(cells));
  }
  return out;
}

double loopArea2(const std::vector<Eigen::Vector2i>& loop) {
  double a = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2i& p = loop[i];
    const Eigen::Vector2i& q = loop[(i + 1) % loop.size()];
    a += double(p.x()) * q.y() - double(q.x()) * p.y();
  }
  return a;
}

}  // namespace

std::vector<Eigen::Vector2d> cellOutline(const GridGeometry& g, const std::vector<int>& cellIndices) {
  // Directed cell edges with the cell on their left (counter-clockwise around each cell), those
  // shared by two cells of the set cancel; the rest chain into loops at the corners.
  const std::set<int> in(cellIndices.begin(), cellIndices.end());
  auto has = [&](int c, int r) { return g.inside(c, r) && in.count(int(g.index(c, r))) > 0; };
  auto key = [](const Eigen::Vector2i& p) { return std::pair{p.x(), p.y()}; };
  std::multimap<std::pair<int, int>, Eigen::Vector2i> next;
  for (int i : cellIndices) {
    const int c = i % g.cols, r = i / g.cols;
    if (!has(c, r - 1)) next.emplace(std::pair{c, r}, Eigen::Vector2i(c + 1, r));
    if (!has(c + 1, r)) next.emplace(std::pair{c + 1, r}, Eigen::Vector2i(c + 1, r + 1));
    if (!has(c, r + 1)) next.emplace(std::pair{c + 1, r + 1}, Eigen::Vector2i(c, r + 1));
    if (!has(c - 1, r)) next.emplace(std::pair{c, r + 1}, Eigen::Vector2i(c, r));
  }
  std::vector<Eigen::Vector2i> best;
  double bestArea = 0;
  while (!next.empty()) {
    std::vector<Eigen::Vector2i> loop;
    Eigen::Vector2i at(next.begin()->first.first, next.begin()->first.second), from = at;
    Eigen::Vector2i heading(0, 0);
    do {
      loop.push_back(at);
      auto [lo, hi] = next.equal_range(key(at));
      auto pick = lo;
      // At a corner two cells share diagonally, turn right of the heading (keeps the loop simple).
      for (auto it = lo; it != hi; ++it) {
        const Eigen::Vector2i d = it->second - at;
        if (heading.x() * d.y() - heading.y() * d.x() < 0) pick = it;
      }
      heading = pick->second - at;
      at = pick->second;
      next.erase(pick);
    } while (at != from && next.count(key(at)) > 0);
    const double a = loopArea2(loop);
    if (a > bestArea) bestArea = a, best = std::move(loop);
  }
  std::vector<Eigen::Vector2d> outline;
  for (size_t i = 0; i < best.size(); ++i) {
    const Eigen::Vector2i& p = best[(i + best.size() - 1) % best.size()];
    const Eigen::Vector2i& q = best[i];
    const Eigen::Vector2i& r = best[(i + 1) % best.size()];
    const Eigen::Vector2i d1 = q - p, d2 = r - q;
    if (d1.x() * d2.y() - d1.y() * d2.x() == 0) continue;  // straight on
    outline.push_back(g.origin + g.resolution * q.cast<double>());
  }
  return outline;
}

std::vector<MissingSurface> findMissingSurfaces(const SurfaceEvidence& evidence, const BoundaryDistance& drivableDistance,
                                                const GroundHeight* groundHeight, const ChangeOptions& options) {
  const GridGeometry& g = evidence.geometry();
  std::vector<uint8_t> mask(g.cellCount(), 0);
  std::vector<float> outside(g.cellCount(), 0.0f);
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      if (evidence.surface(g.index(c, r)) != Surface::Road) continue;
      const Eigen::Vector2d centre = g.cellCentre(c, r);
      double d = drivableDistance.distance(centre);
      if (std::isnan(d)) d = options.missingMinDepth;  // beyond the whole map's field: far from any polygon
      if (!(d > options.missingGap)) continue;
      if (groundHeight && !std::isfinite(groundHeight->heightAt(centre))) continue;
      mask[g.index(c, r)] = 1;
      outside[g.index(c, r)] = float(d);
    }
  std::vector<MissingSurface> out;
  const double cellArea = g.resolution * g.resolution;
  for (const std::vector<int>& cells : components(g, mask)) {
    MissingSurface m;
    m.area = double(cells.size()) * cellArea;
    float bestRange = 1e9f;
    for (int i : cells) {
      const SurfaceCell& cell = evidence.cells()[size_t(i)];
      m.depth = std::max(m.depth, double(outside[size_t(i)]));
      m.roadPoints += cell.road;
      if (cell.firstFrame >= 0 && (m.firstFrame < 0 || cell.firstFrame < m.firstFrame)) m.firstFrame = cell.firstFrame;
      if (cell.bestRange < bestRange) bestRange = cell.bestRange, m.bestFrame = cell.bestFrame;
    }
    if (m.area < options.missingMinArea || m.depth < options.missingMinDepth) continue;
    m.outline = cellOutline(g, cells);
    // Surer the larger it is and the farther it reaches beyond what the map's error could explain.
    m.confidence = (1.0 - std::exp(-m.area / options.missingMinArea)) * std::min(1.0, m.depth / (2.0 * options.missingMinDepth));
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace hdprior
