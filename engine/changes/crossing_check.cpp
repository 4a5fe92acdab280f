#include "engine/changes/crossing_check.h"

#include <algorithm>
#include <cmath>

#include "engine/geom/polygon2d.h"
#include "engine/geom/se2.h"

namespace hdprior {

namespace {

using Vec2 = Eigen::Vector2d;
using Outline = std::vector<Vec2>;

constexpr int kMinCells = 30;           // road cells inside a crossing, and around it, for a verdict
constexpr int kMinControls = 5;         // bare-road outlines a log needs for its road's spread
constexpr double kBrightnessCap = 4.0;  // a cell's mean brightness counts up to this (a kerb's, a sign's)

bool seenEnough(const CrossingBrightness& b) { return b.insideCells >= kMinCells && b.aroundCells >= kMinCells && b.standardError > 0.0; }

// The frame of the most runs among `frames` (sorted), and the first.
std::pair<int, int> firstAndBestFrame(std::vector<int> frames) {
  std::sort(frames.begin(), frames.end());
  int best = -1, most = 0;
  for (size_t i = 0, j; i < frames.size(); i = j) {
    for (j = i; j < frames.size() && frames[j] == frames[i]; ++j) {}
    if (int(j - i) > most) most = int(j - i), best = frames[i];
  }
  return {frames.empty() ? -1 : frames.front(), best};
}

}  // namespace

CrossingEvidence::CrossingEvidence(const VectorMap& map, const ChangeOptions& options)
    : options_(options), lines_(map), cells_(options.paintCell) {
  for (const PedestrianCrossing& c : map.pedestrianCrossings) {
    if (c.edge1.size() < 2 || c.edge2.size() < 2) continue;
    Crossing crossing;
    crossing.verdict.id = c.id;
    crossing.verdict.outline = crossingOutline(c);
    crossing.reach = grownQuad(crossing.verdict.outline, 0.5);
    crossing.explains = grownQuad(crossing.verdict.outline, 1.0);
    crossing.lo = crossing.hi = crossing.explains.front();
    for (const Vec2& p : crossing.explains) crossing.lo = crossing.lo.cwiseMin(p), crossing.hi = crossing.hi.cwiseMax(p);
    crossings_.push_back(std::move(crossing));
  }
}

PaintCell& CrossingEvidence::cellAt(const Vec2& city) {
  const auto [cell, inserted] = cells_.at(city);
  if (inserted) {
    const Vec2 centre = cells_.centreOf(city);
    if (lines_.nearPainted(centre, options_.paintLineReach)) cell.place = uint8_t(Place::PaintedLine);
    else
      for (const Crossing& c : crossings_)
        if ((centre.array() >= c.lo.array()).all() && (centre.array() <= c.hi.array()).all() && ringContains(c.explains, centre))
          cell.place = uint8_t(Place::Crossing);
  }
  return cell;
}

void CrossingEvidence::add(int frame, const SweepPaint& paint, const SE3& cityTEgo) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
  const Vec2 t = cityTEgo.translation().head<2>();
  std::vector<Vec2> road, runs;
  for (const Vec2& p : paint.road) road.push_back(r * p + t);
  for (const PaintRun& run : paint.runs) runs.push_back(r * run.centre + t);
  for (size_t i = 0; i < road.size(); ++i) {
    PaintCell& cell = cellAt(road[i]);
    ++cell.road;
    cell.brightness += paint.brightness[i];
  }
  std::vector<Place> places;
  for (const Vec2& p : runs) {
    PaintCell& cell = cellAt(p);
    ++cell.runs;
    places.push_back(Place(cell.place));
    if (Place(cell.place) == Place::Road) stray_.push_back({p, frame});
  }

  for (Crossing& c : crossings_) {
    const double reach = options_.paintRange + (c.hi - c.lo).norm();
    if ((c.reach[0] - t).norm() > reach) continue;
    int inside = 0, painted = 0;
    for (const Vec2& p : road) inside += ringContains(c.reach, p);
    for (size_t k = 0; k < runs.size(); ++k) painted += places[k] == Place::Crossing && ringContains(c.reach, runs[k]);
    if (inside == 0) continue;
    CrossingVerdict& v = c.verdict;
    if (v.firstFrame < 0) v.firstFrame = frame;
    if (painted > c.bestFrameRuns || (painted == c.bestFrameRuns && inside > c.bestFrameRoadPoints)) {
      c.bestFrameRuns = painted;
      c.bestFrameRoadPoints = inside;
      v.bestFrame = frame;
    }
  }
}

double CrossingEvidence::asphaltShare() const {
  PaintTally t;
  cells_.forEach([&](const Vec2&, const PaintCell& cell) {
    if (Place(cell.place) == Place::Road) t.add(cell);
  });
  return t.road > 0 ? double(t.painted) / t.road : 0.0;
}

std::vector<PaintedCell> CrossingEvidence::paintedCells() const {
  std::vector<PaintedCell> out;
  cells_.forEach([&](const Vec2& centre, const PaintCell& cell) {
    if (cell.road > 0 && cell.runs > 0) out.push_back({centre, Place(cell.place) != Place::Road});
  });
  return out;
}

PaintTally CrossingEvidence::tallyIn(const Outline& outline, Place place) const {
  Vec2 lo = outline.front(), hi = outline.front();
  for (const Vec2& p : outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double s = options_.paintCell;
  PaintTally t;
  for (double x = (std::floor(lo.x() / s) + 0.5) * s; x <= hi.x(); x += s)
    for (double y = (std::floor(lo.y() / s) + 0.5) * s; y <= hi.y(); y += s) {
      if (!ringContains(outline, {x, y})) continue;
      const PaintCell* cell = cells_.find({x, y});
      if (cell && Place(cell->place) == place) t.add(*cell);
    }
  return t;
}

PaintTally CrossingEvidence::tallyInBand(const Vec2& centre, const Vec2& along, double u0, double u1, double v0, double v1) const {
  const Vec2 across(-along.y(), along.x());
  const double s = options_.paintCell;
  PaintTally t;
  for (double u = u0 + s / 2; u < u1; u += s)
    for (double v = v0 + s / 2; v < v1; v += s) {
      const PaintCell* cell = cells_.find(centre + u * along + v * across);
      if (cell && Place(cell->place) == Place::Road) t.add(*cell);
    }
  return t;
}

// Log-likelihood ratio of a tally's painted cells: a painted crossing against the asphalt.
double CrossingEvidence::evidence(const PaintTally& t, double asphaltShare) const {
  return paintEvidence(t, asphaltShare, options_.crossingContrast, options_.crossingPaintShare);
}

CrossingBrightness CrossingEvidence::brightnessOf(const Outline& outline, uint8_t inside) const {
  const Outline outer = grownQuad(outline, 3.0), inner = grownQuad(outline, 1.0);
  Vec2 lo = outer.front(), hi = outer.front();
  for (const Vec2& p : outer) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double s = options_.paintCell;
  double sum[2] = {0, 0}, squares[2] = {0, 0};  // inside, around
  int count[2] = {0, 0};
  for (double x = (std::floor(lo.x() / s) + 0.5) * s; x <= hi.x(); x += s)
    for (double y = (std::floor(lo.y() / s) + 0.5) * s; y <= hi.y(); y += s) {
      const PaintCell* cell = cells_.find({x, y});
      if (!cell || cell->road == 0) continue;
      int k = -1;
      if (cell->place == inside && ringContains(outline, {x, y})) k = 0;
      else if (Place(cell->place) == Place::Road && ringContains(outer, {x, y}) && !ringContains(inner, {x, y})) k = 1;
      if (k < 0) continue;
      const double mean = std::min(kBrightnessCap, double(cell->brightness) / cell->road);
      sum[k] += mean, squares[k] += mean * mean, ++count[k];
    }
  CrossingBrightness b;
  b.insideCells = count[0], b.aroundCells = count[1];
  if (count[0] < 2 || count[1] < 2) return b;
  b.inside = sum[0] / count[0], b.around = sum[1] / count[1];
  const auto varianceOfMean = [&](int k, double mean) { return std::max(0.0, squares[k] / count[k] - mean * mean) / (count[k] - 1); };
  b.standardError = std::sqrt(varianceOfMean(0, b.inside) + varianceOfMean(1, b.around));
  return b;
}

std::pair<double, int> CrossingEvidence::roadSpread() const {
  double squares = 0.0;
  int controls = 0;
  for (const Crossing& c : crossings_) {
    const Vec2 along = (c.verdict.outline[1] - c.verdict.outline[0]).normalized(), normal(-along.y(), along.x());
    for (const double shift : {-24.0, -16.0, -8.0, 8.0, 16.0, 24.0}) {
      Outline moved = c.verdict.outline;
      for (Vec2& p : moved) p += shift * normal;
      const CrossingBrightness b = brightnessOf(moved, uint8_t(Place::Road));
      if (!seenEnough(b)) continue;
      // Its cells' own scatter is in each crossing's standard error already; the spread is the rest.
      squares += b.lift() * b.lift() - b.standardError * b.standardError;
      ++controls;
    }
  }
  return {controls > 0 ? std::sqrt(std::max(0.0, squares / controls)) : 0.0, controls};
}

std::vector<CrossingVerdict> CrossingEvidence::verdicts() const {
  const double share = asphaltShare();
  const auto [spread, controls] = roadSpread();
  std::vector<CrossingVerdict> out;
  std::vector<double> paintedLifts;
  for (const Crossing& c : crossings_) {
    CrossingVerdict v = c.verdict;
    const PaintTally t = tallyIn(c.reach, Place::Crossing);
    v.roadCells = t.road;
    v.paintCells = t.painted;
    v.asphaltShare = share;
    v.brightness = brightnessOf(v.outline, uint8_t(Place::Crossing));
    v.brightness.spread = spread;
    v.controls = controls;
    if (controls >= kMinControls && seenEnough(v.brightness) && v.brightness.z() >= options_.crossingZ) {
      v.verdict = MapVerdict::Consistent;
      v.confidence = evidenceConfidence(v.brightness.z());
      paintedLifts.push_back(v.brightness.lift());
    }
    out.push_back(std::move(v));
  }
  // Faint or worn paint may not stand out: no lift is evidence only against the lift of the log's
  // own painted crossings.
  if (paintedLifts.empty()) return out;
  std::nth_element(paintedLifts.begin(), paintedLifts.begin() + paintedLifts.size() / 2, paintedLifts.end());
  const double painted = paintedLifts[paintedLifts.size() / 2];
  for (CrossingVerdict& v : out) {
    v.paintedLift = painted;
    const CrossingBrightness& b = v.brightness;
    if (v.verdict != MapVerdict::Unobserved || !seenEnough(b)) continue;
    const double below = (painted - b.lift()) / b.uncertainty();
    if (b.z() <= options_.crossingAbsentZ && below >= options_.crossingZ) {
      v.verdict = MapVerdict::Contradicted;
      v.confidence = evidenceConfidence(below);
    }
  }
  return out;
}

std::vector<MissingCrossing> CrossingEvidence::missing() const {
  const double share = asphaltShare();
  const double d = options_.crossingDepth, w = options_.crossingWidth;
  struct Candidate {
    Vec2 centre, along;
    double evidence;
  };
  std::vector<Candidate> candidates;
  std::unordered_set<int64_t> tried;  // one candidate per metre square
  for (const StrayRun& s : stray_) {
    if (!tried.insert((int64_t(std::floor(s.city.x())) << 32) ^ (int64_t(std::floor(s.city.y())) & 0xffffffff)).second) continue;
    const std::optional<Vec2> along = lines_.directionAt(s.city, 15.0);
    if (!along) continue;
    // Painted at both edges (a crossing's edge lines or its stripes' ends; a stop line has one), not in the flanks.
    const PaintTally near = tallyInBand(s.city, *along, -d / 2, -d / 6, -w / 2, w / 2), middle = tallyInBand(s.city, *along, -d / 6, d / 6, -w / 2, w / 2),
                far = tallyInBand(s.city, *along, d / 6, d / 2, -w / 2, w / 2);
    if (evidence(near, share) <= 0.0 || evidence(far, share) <= 0.0) continue;
    const PaintTally band{near.road + middle.road + far.road, near.painted + middle.painted + far.painted};
    // A band seen over less than a third of it is a glimpse.
    if (band.road < d * w / (3.0 * options_.paintCell * options_.paintCell)) continue;
    const double e = evidence(band, share);
    if (e < options_.missingCrossingEvidence) continue;
    const PaintTally before = tallyInBand(s.city, *along, -1.5 * d - 1.0, -d / 2 - 1.0, -w / 2, w / 2),
                after = tallyInBand(s.city, *along, d / 2 + 1.0, 1.5 * d + 1.0, -w / 2, w / 2);
    if (evidence({before.road + after.road, before.painted + after.painted}, share) > 0.0) continue;
    candidates.push_back({s.city, *along, e});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.evidence > b.evidence; });

  std::vector<MissingCrossing> out;
  std::vector<Outline> taken;  // the crossings found, grown by their depth: one crossing is one report
  for (const Candidate& c : candidates) {
    if (std::any_of(taken.begin(), taken.end(), [&](const Outline& o) { return ringContains(o, c.centre); })) continue;
    // Across the lanes as far as metre-wide slices of the band stay painted like a crossing (or
    // are a painted lane line's).
    const auto painted = [&](double v0, double v1) {
      const PaintTally t = tallyInBand(c.centre, c.along, -d / 2, d / 2, v0, v1);
      return (t.road == 0 && lines_.nearPainted(c.centre + (v0 + v1) / 2 * Vec2(-c.along.y(), c.along.x()), options_.paintLineReach)) ||
             evidence(t, share) > 0.0;
    };
    double lo = -w / 2, hi = w / 2;
    while (hi < 15.0 && painted(hi, hi + 1.0)) hi += 1.0;
    while (lo > -15.0 && painted(lo - 1.0, lo)) lo -= 1.0;
    const Vec2 across(-c.along.y(), c.along.x());
    const auto at = [&](double u, double v) { return Vec2(c.centre + u * c.along + v * across); };
    MissingCrossing m;
    m.outline = {at(-d / 2, lo), at(d / 2, lo), at(d / 2, hi), at(-d / 2, hi)};
    const PaintTally t = tallyInBand(c.centre, c.along, -d / 2, d / 2, lo, hi);
    m.roadCells = t.road;
    m.paintCells = t.painted;
    m.confidence = evidenceConfidence(evidence(t, share));
    std::vector<int> frames;
    for (const StrayRun& s : stray_)
      if (ringContains(m.outline, s.city)) frames.push_back(s.frame);
    std::tie(m.firstFrame, m.bestFrame) = firstAndBestFrame(std::move(frames));
    if (signedArea(m.outline) < 0) std::reverse(m.outline.begin(), m.outline.end());
    taken.push_back(grownQuad(m.outline, d));
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace hdprior
