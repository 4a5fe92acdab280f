#include "engine/changes/boundary_stretch.h"

#include <algorithm>
#include <cmath>

#include "engine/changes/boundary_reading.h"
#include "engine/changes/boundary_samples.h"
#include "engine/changes/polygon_offset.h"
#include "engine/map/boundary_distance.h"

namespace hdprior {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

double saturation(int samples, int scale) { return 1.0 - std::exp(-double(samples) / double(scale)); }

struct Reading {
  BoundarySample sample;
  BoundaryReading reading;
};

bool contradicts(const BoundaryReading& r, const ChangeOptions& o) {
  return (r.kind == BoundaryReading::Kind::Edge || r.kind == BoundaryReading::Kind::AcrossGap) && std::abs(r.offset) > o.tolerance;
}

std::string evidenceOf(double offset, bool contradicted, bool acrossGap) {
  if (!contradicted) return "kerb_offset";
  if (acrossGap) return "road_across_gap";
  return offset > 0 ? "road_beyond_boundary" : "kerb_inside";
}

// Where the map's drivable area begins again outwards of a sample, within the reach; NaN if it does not.
double drivableResumes(const BoundarySample& s, const BoundaryDistance& drivableDistance, const ChangeOptions& o) {
  for (double t = o.cell / 2; t <= o.reach; t += o.cell / 2)
    if (drivableDistance.distance(s.point + t * s.normal) < 0.0) return t;
  return NAN;
}

// A narrowed polygon leaves a gap to its neighbour that the road goes on across: the road the
// lidar saw runs past the boundary as far as the map's next drivable area at least.
BoundaryReading acrossGap(BoundaryReading r, const BoundarySample& s, const BoundaryDistance& drivableDistance, const ChangeOptions& o) {
  if (r.kind != BoundaryReading::Kind::Open) return r;
  const double resumes = drivableResumes(s, drivableDistance, o);
  if (std::isfinite(resumes)) r.kind = BoundaryReading::Kind::AcrossGap, r.offset = resumes;
  return r;
}

BoundaryStretch judge(const DrivableArea& area, int index, double a0, double a1, const std::vector<Reading>& readings,
                      const ChangeOptions& o) {
  BoundaryStretch s;
  s.areaId = area.id;
  s.index = index;
  s.line = boundaryBetween(area.areaBoundary, a0, a1);
  s.samples = int(readings.size());
  std::vector<double> observed, against;
  int againstAcrossGap = 0;
  double nearestAgainst = 1e9, nearestObserved = 1e9;
  double ground = 0;
  int groundCount = 0;
  for (const Reading& r : readings) {
    const BoundaryReading& b = r.reading;
    if (b.kind == BoundaryReading::Kind::Unobserved) continue;
    if (b.kind == BoundaryReading::Kind::Open) {
      ++s.open;
      continue;
    }
    if (contradicts(b, o) && b.nearestView > o.edgeRange) continue;
    ++s.observed;
    observed.push_back(b.offset);
    nearestObserved = std::min<double>(nearestObserved, b.nearestView);
    if (contradicts(b, o)) {
      against.push_back(b.offset);
      againstAcrossGap += b.kind == BoundaryReading::Kind::AcrossGap;
      nearestAgainst = std::min<double>(nearestAgainst, b.nearestView);
    }
    s.curbPoints += b.curbPoints;
    if (std::isfinite(b.groundOffset)) ground += b.groundOffset, ++groundCount;
    if (b.firstFrame >= 0 && (s.firstFrame < 0 || b.firstFrame < s.firstFrame)) s.firstFrame = b.firstFrame;
    if (s.bestFrame < 0 && b.bestFrame >= 0) s.bestFrame = b.bestFrame;
  }
  s.contradicted = int(against.size());
  s.groundOffset = groundCount > 0 ? ground / groundCount : NAN;
  if (s.observed < o.minSamples) {
    if (s.open >= o.minSamples) s.evidence = "road_continues";
    return s;
  }
  const double share = double(s.contradicted) / double(s.observed);
  const bool contradicted = s.contradicted >= o.minSamples && share >= o.contradictedShare;
  // Too few contradicting samples to contradict the map and too many to agree with it: nothing is
  // said, and the evidence names what the few saw. A kerb inside the boundary is also what a raised
  // island the map paints over, or a road the walk labelled in patches, shows: it takes twice the
  // samples.
  const bool undecided = !contradicted && share >= o.contradictedShare;
  const bool islandLike = contradicted && median(against) < 0 && s.contradicted < 2 * o.minSamples;
  if (undecided || islandLike) {
    s.offset = median(against);
    s.evidence = evidenceOf(s.offset, true, 2 * againstAcrossGap > s.contradicted);
    return s;
  }
  s.verdict = contradicted ? MapVerdict::Contradicted : MapVerdict::Consistent;
  s.offset = median(contradicted ? against : observed);
  s.evidence = evidenceOf(s.offset, contradicted, 2 * againstAcrossGap > s.contradicted);
  s.nearestView = contradicted ? nearestAgainst : nearestObserved;
  s.confidence = contradicted ? share * saturation(s.contradicted, o.minSamples)
                              : (1.0 - share) * saturation(s.observed - s.contradicted, o.minSamples);
  return s;
}

// The edges seen near enough to place them (ChangeOptions::edgeRange), of one stretch or of all.
std::vector<EdgeOffset> edgeOffsets(const std::vector<Reading>& readings, const ChangeOptions& o) {
  std::vector<EdgeOffset> out;
  for (const Reading& r : readings)
    if (r.reading.kind == BoundaryReading::Kind::Edge && r.reading.nearestView <= o.edgeRange) out.push_back({r.sample.point, r.sample.normal, r.reading.offset});
  return out;
}

// A stretch not contradicted on its own whose edges lie where the polygon's offset puts them.
void judgeByPolygon(BoundaryStretch& s, const PolygonOffset& polygon, const std::vector<Reading>& readings, const ChangeOptions& o) {
  std::vector<double> explained;
  const std::vector<EdgeOffset> edges = edgeOffsets(readings, o);
  for (const EdgeOffset& e : edges)
    if (polygon.explains(e, o)) explained.push_back(e.offset);
  if (explained.empty() || 2 * explained.size() < edges.size()) return;
  s.verdict = MapVerdict::Contradicted;
  s.evidence = "polygon_offset";
  s.offset = median(explained);
  s.polygonShift = polygon.translation;
  s.confidence = polygon.fitShare * saturation(polygon.samples, o.polygonMinSamples);
  for (const Reading& r : readings)
    if (r.reading.kind == BoundaryReading::Kind::Edge) s.nearestView = std::min<double>(s.nearestView, r.reading.nearestView);
}

}  // namespace

namespace {

// One polygon's boundary samples, read, by stretch.
struct ReadBoundary {
  const DrivableArea* area = nullptr;
  double length = 0.0;
  std::vector<std::vector<Reading>> byStretch;
  std::vector<bool> onBoundary;
  std::vector<EdgeOffset> edges;
};

ReadBoundary readArea(const DrivableArea& area, const SurfaceEvidence& evidence, const BoundaryDistance& drivableDistance,
                      const ChangeOptions& options) {
  ReadBoundary r;
  r.area = &area;
  r.length = perimeter(area.areaBoundary);
  const size_t stretches = size_t(std::max(1, int(std::round(r.length / options.stretchLength))));
  r.byStretch.resize(stretches);
  r.onBoundary.assign(stretches, false);
  for (const BoundarySample& s : sampleBoundary(area.areaBoundary, options.sampleSpacing)) {
    const size_t k = std::min(stretches - 1, size_t(s.arc / r.length * double(stretches)));
    const double inside = drivableDistance.distance(s.point);
    if (!(std::abs(inside) <= options.seamDepth)) continue;  // a seam, or outside the distance field
    r.onBoundary[k] = true;
    if (!evidence.cellAt(s.point)) continue;
    r.byStretch[k].push_back({s, acrossGap(readBoundary(evidence, s, options), s, drivableDistance, options)});
  }
  for (const std::vector<Reading>& readings : r.byStretch)
    for (const EdgeOffset& e : edgeOffsets(readings, options)) r.edges.push_back(e);
  return r;
}

std::vector<EdgeOffset> edgesAround(const std::vector<ReadBoundary>& areas, size_t except) {
  std::vector<EdgeOffset> out;
  for (size_t i = 0; i < areas.size(); ++i)
    if (i != except) out.insert(out.end(), areas[i].edges.begin(), areas[i].edges.end());
  return out;
}

}  // namespace

std::vector<BoundaryStretch> checkBoundaries(const std::vector<DrivableArea>& areas, const SurfaceEvidence& evidence,
                                             const BoundaryDistance& drivableDistance, const ChangeOptions& options) {
  std::vector<ReadBoundary> read;
  for (const DrivableArea& area : areas) read.push_back(readArea(area, evidence, drivableDistance, options));
  std::vector<BoundaryStretch> out;
  for (size_t i = 0; i < read.size(); ++i) {
    const ReadBoundary& r = read[i];
    std::optional<PolygonOffset> polygon;
    if (int(r.edges.size()) >= options.polygonMinSamples) polygon = polygonOffset(r.edges, edgesAround(read, i), options);
    const int stretches = int(r.byStretch.size());
    for (int k = 0; k < stretches; ++k) {
      if (!r.onBoundary[size_t(k)]) continue;
      const std::vector<Reading>& readings = r.byStretch[size_t(k)];
      out.push_back(judge(*r.area, k, k * r.length / stretches, (k + 1) * r.length / stretches, readings, options));
      if (polygon && out.back().verdict != MapVerdict::Contradicted) judgeByPolygon(out.back(), *polygon, readings, options);
    }
  }
  return out;
}

}  // namespace hdprior
