#include "engine/changes/boundary_reading.h"

#include <cmath>
#include <vector>

namespace hdprior {

namespace {

enum class Ground { Unknown, Road, OffRoad };

// The cells across the boundary, `step` apart along the normal, each summed over three
// cells side by side (half a metre either way along the boundary).
struct Profile {
  double step = 0.25;
  int half = 0;  // index of offset 0
  std::vector<SurfaceCell> cells;
  std::vector<int> road, notRoad;  // of the three cells
  double offset(int i) const { return (i - half) * step; }
  int index(double offset) const { return half + int(std::lround(offset / step)); }
  Ground ground(int i) const {
    if (road[size_t(i)] > 0 && road[size_t(i)] >= notRoad[size_t(i)]) return Ground::Road;
    return notRoad[size_t(i)] > 0 ? Ground::OffRoad : Ground::Unknown;
  }
};

void accumulate(SurfaceCell& sum, const SurfaceCell& c) {
  sum.road = uint16_t(std::min(65535, sum.road + c.road));
  sum.offRoad = uint16_t(std::min(65535, sum.offRoad + c.offRoad));
  sum.curb = uint16_t(std::min(65535, sum.curb + c.curb));
  sum.groundOffsetSum += c.groundOffsetSum;
  sum.groundOffsetCount = uint16_t(std::min(65535, sum.groundOffsetCount + c.groundOffsetCount));
  if (c.firstFrame >= 0 && (sum.firstFrame < 0 || c.firstFrame < sum.firstFrame)) sum.firstFrame = c.firstFrame;
  if (c.bestFrame >= 0 && c.bestRange < sum.bestRange) {
    sum.bestRange = c.bestRange;
    sum.bestFrame = c.bestFrame;
  }
}

Profile profileAcross(const SurfaceEvidence& evidence, const BoundarySample& s, const ChangeOptions& o) {
  Profile p;
  p.step = o.cell / 2;
  p.half = int(std::lround(o.reach / p.step));
  const size_t n = size_t(2 * p.half + 1);
  p.cells.resize(n);
  p.road.assign(n, 0);
  p.notRoad.assign(n, 0);
  const Eigen::Vector2d along(-s.normal.y(), s.normal.x());
  for (int i = 0; i < int(n); ++i)
    for (double t : {-o.cell, 0.0, o.cell}) {
      const Eigen::Vector2d at = s.point + p.offset(i) * s.normal + t * along;
      if (const SurfaceCell* c = evidence.cellAt(at)) accumulate(p.cells[size_t(i)], *c);
      const Surface surface = evidence.surfaceAt(at);
      p.road[size_t(i)] += surface == Surface::Road;
      p.notRoad[size_t(i)] += surface == Surface::NotRoad;
    }
  return p;
}

// Walks outwards over road from index i (a road cell); one unknown cell is stepped over.
// Returns the last road index, or -1 when road reaches the end of the profile.
int lastRoadOutwards(const Profile& p, int i) {
  const int n = int(p.cells.size());
  int last = i;
  for (int j = i + 1; j < n; ++j) {
    const Ground g = p.ground(j);
    if (g == Ground::Road) last = j;
    else if (g == Ground::OffRoad || j - last > 2) break;
  }
  return last >= n - 1 ? -1 : last;
}

// Whether the lidar saw what ends the road just after index `last`: ground that is not road, or a kerb.
bool edgeSeen(const Profile& p, int last, double within) {
  const int n = int(p.cells.size()), reach = int(std::lround(within / p.step));
  for (int j = last; j <= std::min(n - 1, last + reach); ++j) {
    if (p.cells[size_t(j)].curb > 0 && j == last) return true;
    if (j > last && p.ground(j) == Ground::OffRoad) return true;
    if (j > last && p.ground(j) == Ground::Road) return false;
  }
  return false;
}

void describe(BoundaryReading& r, const Profile& p, int at) {
  SurfaceCell sum;
  for (int j = std::max(0, at - 4); j <= std::min(int(p.cells.size()) - 1, at + 4); ++j) accumulate(sum, p.cells[size_t(j)]);
  r.curbPoints = sum.curb;
  r.firstFrame = sum.firstFrame;
  r.bestFrame = sum.bestFrame;
  r.nearestView = sum.bestRange;
  SurfaceCell all;
  for (const SurfaceCell& c : p.cells) accumulate(all, c);
  r.groundOffset = all.groundOffsetCount > 0 ? all.groundOffsetSum / float(all.groundOffsetCount) : NAN;
}

}  // namespace

BoundaryReading readBoundary(const SurfaceEvidence& evidence, const BoundarySample& sample, const ChangeOptions& options) {
  const Profile p = profileAcross(evidence, sample, options);
  const int n = int(p.cells.size());
  BoundaryReading r;
  // The road nearest the boundary on its inside, within 3 m.
  int start = -1;
  for (int i = p.half; i >= std::max(0, p.index(-3.0)); --i)
    if (p.ground(i) == Ground::Road) {
      start = i;
      break;
    }
  if (start >= 0) {
    const int last = lastRoadOutwards(p, start);
    if (last < 0) {
      r.kind = BoundaryReading::Kind::Open;
      r.offset = options.reach;
      describe(r, p, n - 1);
    } else if (edgeSeen(p, last, 1.5)) {
      r.kind = BoundaryReading::Kind::Edge;
      r.offset = p.offset(last) + p.step / 2;
      describe(r, p, last);
      // Inside the boundary the walk also stops at parked cars and gaps: only a kerb it saw counts.
      if (r.offset < -options.tolerance && r.curbPoints < options.minSamples) return BoundaryReading{};
    }
    return r;
  }
  // No road just inside: the road walk may not have come this far (a cross street, the far side
  // beyond parked cars), so nothing is read here.
  return r;
}

}  // namespace hdprior
