#include "engine/changes/crossing_check.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include "engine/geom/polygon2d.h"
#include "engine/geom/se2.h"

namespace hdprior {

namespace {

using Vec2 = Eigen::Vector2d;
using Outline = std::vector<Vec2>;

int64_t cellKey(const Vec2& city) {
  return (int64_t(std::floor(city.x())) << 32) ^ (int64_t(std::floor(city.y())) & 0xffffffff);
}

// Log-likelihood ratio of `runs` paint runs over `road` points: a painted crossing against asphalt.
double paintEvidence(int runs, int road, const ChangeOptions& o) {
  return runs * std::log(o.crossingPaintRate / o.asphaltPaintRate) - road * (o.crossingPaintRate - o.asphaltPaintRate);
}

double confidenceOf(double evidence) { return 1.0 / (1.0 + std::exp(-std::abs(evidence))); }

// Stray runs joined when within `link` metres of each other (single linkage).
std::vector<std::vector<size_t>> clusters(const std::vector<Vec2>& points, double link) {
  std::vector<int> group(points.size(), -1);
  std::vector<std::vector<size_t>> out;
  for (size_t seed = 0; seed < points.size(); ++seed) {
    if (group[seed] >= 0) continue;
    group[seed] = int(out.size());
    std::vector<size_t> members{seed};
    for (size_t k = 0; k < members.size(); ++k)
      for (size_t j = 0; j < points.size(); ++j)
        if (group[j] < 0 && (points[j] - points[members[k]]).norm() <= link) {
          group[j] = group[seed];
          members.push_back(j);
        }
    out.push_back(std::move(members));
  }
  return out;
}

// Points' rectangle along their principal axes, grown by a margin: its sides (long first) and long axis.
struct Patch {
  Outline outline;
  Vec2 extent, axis;
};

Patch principalRectangle(const std::vector<Vec2>& points, double margin) {
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const Vec2& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  const Vec2 u = eig.eigenvectors().col(1), v(-u.y(), u.x());
  Vec2 lo(1e9, 1e9), hi(-1e9, -1e9);
  for (const Vec2& p : points) {
    const Vec2 q((p - mean).dot(u), (p - mean).dot(v));
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Vec2 extent = hi - lo;
  lo -= Vec2(margin, margin);
  hi += Vec2(margin, margin);
  auto at = [&](double a, double b) { return Vec2(mean + a * u + b * v); };
  return {{at(lo.x(), lo.y()), at(hi.x(), lo.y()), at(hi.x(), hi.y()), at(lo.x(), hi.y())}, extent, u};
}

}  // namespace

CrossingEvidence::CrossingEvidence(const VectorMap& map, const ChangeOptions& options) : options_(options) {
  for (const PedestrianCrossing& c : map.pedestrianCrossings) {
    if (c.edge1.size() < 2 || c.edge2.size() < 2) continue;
    Crossing crossing;
    crossing.verdict.id = c.id;
    crossing.verdict.outline = crossingOutline(c);
    crossing.reach = grownQuad(crossing.verdict.outline, 0.5);
    crossing.explains = grownQuad(crossing.verdict.outline, 1.0);
    crossings_.push_back(std::move(crossing));
  }
  for (const LaneSegment& lane : map.laneSegments)
    for (const auto& [line, type] : {std::pair{&lane.leftLaneBoundary, &lane.leftLaneMarkType},
                                     std::pair{&lane.rightLaneBoundary, &lane.rightLaneMarkType}})
      if (line->size() >= 2) {
        std::vector<Vec2> planar;
        for (const Eigen::Vector3d& p : *line) planar.push_back(p.head<2>());
        (isPaintedMark(*type) ? paintedLines_ : unpaintedLines_).push_back(std::move(planar));
      }
}

bool CrossingEvidence::onPaintedLine(const Vec2& city) const {
  const Vec2 point[1] = {city};
  for (const std::vector<Vec2>& line : paintedLines_)
    if (polylineDistance(point, line, false) <= options_.paintLineReach) return true;
  return false;
}

std::optional<Vec2> CrossingEvidence::laneDirectionAt(const Vec2& city) const {
  double best = 15.0;
  std::optional<Vec2> direction;
  for (const auto* lines : {&paintedLines_, &unpaintedLines_})
    for (const std::vector<Vec2>& line : *lines)
      for (size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2 a[1] = {city}, segment[2] = {line[i], line[i + 1]};
        const double d = polylineDistance(a, segment, false);
        if (d < best && (line[i + 1] - line[i]).norm() > 1e-6) best = d, direction = (line[i + 1] - line[i]).normalized();
      }
  return direction;
}

void CrossingEvidence::add(int frame, const SweepPaint& paint, const SE3& cityTEgo) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
  const Vec2 t = cityTEgo.translation().head<2>();
  std::vector<Vec2> road, runs;
  for (const Vec2& p : paint.road) road.push_back(r * p + t);
  for (const PaintRun& run : paint.runs) runs.push_back(r * run.centre + t);
  for (const Vec2& p : road) ++roadCells_[cellKey(p)];

  std::vector<bool> explained(runs.size(), false), onLine(runs.size());
  for (size_t k = 0; k < runs.size(); ++k) onLine[k] = onPaintedLine(runs[k]);
  for (Crossing& c : crossings_) {
    const double reach = options_.paintRange + (c.reach[0] - c.reach[2]).norm() + (c.reach[1] - c.reach[3]).norm();
    if ((c.reach[0] - t).norm() > reach) continue;
    int inside = 0, painted = 0;
    for (const Vec2& p : road) inside += ringContains(c.reach, p);
    for (size_t k = 0; k < runs.size(); ++k)
      if (ringContains(c.explains, runs[k])) {
        explained[k] = true;
        painted += !onLine[k] && ringContains(c.reach, runs[k]);
      }
    if (inside == 0) continue;
    CrossingVerdict& v = c.verdict;
    v.roadPoints += inside;
    v.paintRuns += painted;
    if (v.firstFrame < 0) v.firstFrame = frame;
    if (painted > c.bestFrameRuns || (painted == c.bestFrameRuns && inside > c.bestFrameRoadPoints)) {
      c.bestFrameRuns = painted;
      c.bestFrameRoadPoints = inside;
      v.bestFrame = frame;
    }
  }
  for (size_t k = 0; k < runs.size(); ++k)
    if (!explained[k] && !onLine[k]) stray_.push_back({runs[k], frame});
}

int CrossingEvidence::roadPointsIn(const Outline& outline) const {
  Vec2 lo = outline.front(), hi = outline.front();
  for (const Vec2& p : outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  int count = 0;
  for (double x = std::floor(lo.x()); x <= hi.x(); x += 1.0)
    for (double y = std::floor(lo.y()); y <= hi.y(); y += 1.0) {
      const Vec2 cell(x, y);
      if (!ringContains(outline, cell + Vec2(0.5, 0.5))) continue;
      const auto it = roadCells_.find(cellKey(cell));
      if (it != roadCells_.end()) count += it->second;
    }
  return count;
}

std::vector<CrossingVerdict> CrossingEvidence::verdicts() const {
  std::vector<CrossingVerdict> out;
  for (const Crossing& c : crossings_) {
    CrossingVerdict v = c.verdict;
    const double evidence = paintEvidence(v.paintRuns, v.roadPoints, options_);
    v.verdict = evidence >= options_.crossingEvidence    ? MapVerdict::Consistent
                : evidence <= -options_.crossingEvidence ? MapVerdict::Contradicted
                                                         : MapVerdict::Unobserved;
    v.confidence = v.verdict == MapVerdict::Unobserved ? 0.0 : confidenceOf(evidence);
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<MissingCrossing> CrossingEvidence::missing() const {
  std::vector<Vec2> points;
  for (const StrayRun& s : stray_) points.push_back(s.city);
  std::vector<MissingCrossing> out;
  // 2.5 m: a crossing whose paint the lane lines' reach cuts in two is one patch again.
  for (const std::vector<size_t>& members : clusters(points, 2.5)) {
    std::vector<Vec2> patch;
    MissingCrossing m;
    std::vector<int> frames;
    for (size_t k : members) {
      patch.push_back(points[k]);
      frames.push_back(stray_[k].frame);
    }
    if (patch.size() < 3) continue;
    const Patch rectangle = principalRectangle(patch, 0.5);
    if (rectangle.extent.minCoeff() < options_.missingCrossingExtent) continue;
    // A crossing runs across the lanes; paint along them is a lane line the map lacks or misplaces.
    const std::optional<Vec2> lane = laneDirectionAt(rectangle.outline[0] / 2 + rectangle.outline[2] / 2);
    if (lane && std::abs(lane->dot(rectangle.axis)) > std::cos(options_.crossingAngle)) continue;
    m.outline = rectangle.outline;
    m.paintRuns = int(patch.size());
    const double evidence = paintEvidence(m.paintRuns, roadPointsIn(m.outline), options_);
    if (evidence < options_.crossingEvidence) continue;
    m.confidence = confidenceOf(evidence);
    std::sort(frames.begin(), frames.end());
    m.firstFrame = frames.front();
    int best = 0;  // the frame with most of the patch's runs
    for (size_t i = 0, j; i < frames.size(); i = j) {
      for (j = i; j < frames.size() && frames[j] == frames[i]; ++j) {}
      if (int(j - i) > best) best = int(j - i), m.bestFrame = frames[i];
    }
    if (signedArea(m.outline) < 0) std::reverse(m.outline.begin(), m.outline.end());
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace hdprior
