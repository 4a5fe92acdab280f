#include "engine/changes/crossing_check.h"

#include <algorithm>
#include <cmath>

#include "engine/geom/polygon2d.h"
#include "engine/geom/se2.h"

namespace hdprior {

namespace {

using Vec2 = Eigen::Vector2d;
using Outline = std::vector<Vec2>;

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
  for (const Vec2& p : road) ++cellAt(p).road;
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

std::vector<CrossingVerdict> CrossingEvidence::verdicts() const {
  const double share = asphaltShare();
  std::vector<CrossingVerdict> out;
  for (const Crossing& c : crossings_) {
    CrossingVerdict v = c.verdict;
    const PaintTally t = tallyIn(c.reach, Place::Crossing);
    v.roadCells = t.road;
    v.paintCells = t.painted;
    v.asphaltShare = share;
    const double e = evidence(t, share);
    const bool asAsphalt = t.painted <= options_.crossingAsphaltLevel * share * t.road;
    v.verdict = e >= options_.crossingEvidence                  ? MapVerdict::Consistent
                : e <= -options_.crossingEvidence && asAsphalt ? MapVerdict::Contradicted
                                                               : MapVerdict::Unobserved;
    v.confidence = v.verdict == MapVerdict::Unobserved ? 0.0 : evidenceConfidence(e);
    out.push_back(std::move(v));
  }
  // Faint or worn paint reads as asphalt: no paint is evidence only in a log whose crossings show it.
  const bool paintShows = std::any_of(out.begin(), out.end(), [](const CrossingVerdict& v) { return v.verdict == MapVerdict::Consistent; });
  for (CrossingVerdict& v : out)
    if (!paintShows && v.verdict == MapVerdict::Contradicted) v.verdict = MapVerdict::Unobserved, v.confidence = 0.0;
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
