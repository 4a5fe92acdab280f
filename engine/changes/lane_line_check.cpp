#include "engine/changes/lane_line_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "engine/geom/polygon2d.h"
#include "engine/geom/se2.h"

namespace hdprior {

namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kCell = 5.0;       // metres, of the index of stretches
constexpr double kBin = 0.25;       // metres, of the offset histogram
constexpr double kReach = 2.0;      // metres beside a line that its stretch reads
constexpr double kOnLine = 0.5;     // paint this near the line is the line's
constexpr double kMinOffset = 0.75; // paint nearer than this may be the line seen through a pose error

int64_t indexKey(long cx, long cy) { return (int64_t(cx) << 32) ^ (int64_t(cy) & 0xffffffff); }

// The pieces of a polyline every `length` metres of arc (the last one may be shorter).
std::vector<std::vector<Vec2>> piecesOf(const Polyline3& line, double length) {
  std::vector<std::vector<Vec2>> out(1);
  double arc = 0.0;
  out.back().push_back(line.front().head<2>());
  for (size_t i = 1; i < line.size(); ++i) {
    Vec2 a = line[i - 1].head<2>();
    const Vec2 b = line[i].head<2>();
    while (arc + (b - a).norm() > length) {
      const Vec2 cut = a + (b - a).normalized() * (length - arc);
      out.back().push_back(cut);
      out.push_back({cut});
      a = cut;
      arc = 0.0;
    }
    arc += (b - a).norm();
    out.back().push_back(b);
  }
  if (out.back().size() < 2) out.pop_back();
  return out;
}

}  // namespace

LaneLineEvidence::LaneLineEvidence(const VectorMap& map, const ChangeOptions& options)
    : options_(options), paint_(options.paintCell) {
  std::set<LaneLineKey> seen;
  for (const LaneSegment& lane : map.laneSegments)
    for (const auto& [line, type, side] : {std::tuple{&lane.leftLaneBoundary, &lane.leftLaneMarkType, "left"},
                                           std::tuple{&lane.rightLaneBoundary, &lane.rightLaneMarkType, "right"}}) {
      if (line->size() < 2 || !isPaintedMark(*type) || !seen.insert(laneLineKey(*line)).second) continue;
      int index = 0;
      for (std::vector<Vec2>& piece : piecesOf(*line, options.stretchLength)) {
        Stretch s;
        s.judged.laneId = lane.id;
        s.judged.side = side;
        s.judged.markType = *type;
        s.judged.index = index++;
        s.judged.line = std::move(piece);
        const size_t k = stretches_.size();
        std::set<int64_t> cells;
        for (const Vec2& p : s.judged.line)
          for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) cells.insert(indexKey(long(std::floor(p.x() / kCell)) + dx, long(std::floor(p.y() / kCell)) + dy));
        for (int64_t c : cells) cells_[c].push_back(k);
        stretches_.push_back(std::move(s));
      }
    }
  for (const PedestrianCrossing& c : map.pedestrianCrossings)
    if (c.edge1.size() >= 2 && c.edge2.size() >= 2) crossings_.push_back(grownQuad(crossingOutline(c), 1.0));
}

void LaneLineEvidence::add(int frame, const SweepPaint& paint, const SE3& cityTEgo) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
  const Vec2 t = cityTEgo.translation().head<2>();
  std::vector<std::pair<Vec2, std::optional<size_t>>> runs;  // each run in the city and the stretch it is beside
  int on = 0, off = 0;
  std::set<std::pair<int64_t, std::string>> offLines;  // the lines with paint beside them
  for (const PaintRun& run : paint.runs) {
    if (run.centre.norm() > options_.laneRange) continue;
    const Vec2 city = r * run.centre + t;
    const std::optional<std::pair<size_t, double>> b = nearestStretch(city);
    runs.push_back({city, b ? std::optional<size_t>(b->first) : std::nullopt});
    if (!b) continue;
    on += std::abs(b->second) < kOnLine;
    if (std::abs(b->second) >= kMinOffset) {
      ++off;
      offLines.insert({stretches_[b->first].judged.laneId, stretches_[b->first].judged.side});
    }
  }
  // A map change moves one line; a pose that is off moves the paint of every line in view.
  if (off >= 3 && off > on && (offLines.size() >= 2 || on == 0)) {
    ++misalignedFrames_;
    return;
  }
  for (const Vec2& p : paint.road)
    if (p.norm() <= options_.laneRange) ++paint_.at(r * p + t).first.road;
  for (const auto& [city, stretch] : runs) {
    ++paint_.at(city).first.runs;
    if (stretch) addRun(frame, stretches_[*stretch]);
  }
}

std::optional<std::pair<size_t, double>> LaneLineEvidence::nearestStretch(const Vec2& city) const {
  for (const auto& crossing : crossings_)
    if (ringContains(crossing, city)) return std::nullopt;
  const auto cell = cells_.find(indexKey(long(std::floor(city.x() / kCell)), long(std::floor(city.y() / kCell))));
  if (cell == cells_.end()) return std::nullopt;
  std::optional<std::pair<size_t, double>> best;
  for (size_t k : cell->second) {
    const std::optional<double> o = leftOffset(stretches_[k].judged.line, city);
    if (o && std::abs(*o) < kReach && (!best || std::abs(*o) < std::abs(best->second))) best = {k, *o};
  }
  return best;
}

void LaneLineEvidence::addRun(int frame, Stretch& s) {
  if (s.judged.firstFrame < 0) s.judged.firstFrame = frame;
  s.frameRuns = s.lastFrame == frame ? s.frameRuns + 1 : 1;
  s.lastFrame = frame;
  if (s.frameRuns > s.bestRuns) s.bestRuns = s.frameRuns, s.judged.bestFrame = frame;
}

std::vector<LaneLineEvidence::Profile> LaneLineEvidence::profiles() const {
  std::vector<Profile> out(stretches_.size());
  paint_.forEach([&](const Vec2& centre, const PaintCell& cell) {
    if (cell.road == 0) return;
    const std::optional<std::pair<size_t, double>> b = nearestStretch(centre);
    if (b) out[b->first][std::clamp(int(std::floor((b->second + kReach) / kBin)), 0, kBins - 1)].add(cell);
  });
  return out;
}

std::vector<LaneLineStretch> LaneLineEvidence::stretches(double asphaltShare) const {
  const std::vector<Profile> profile = profiles();
  // A line is judged whole: a stretch shows a few painted cells, too few to tell paint from asphalt.
  struct Line {
    Profile profile{};
    int firstFrame = -1, bestFrame = -1, bestRuns = 0;
  };
  std::map<std::pair<int64_t, std::string>, Line> lines;
  for (size_t k = 0; k < stretches_.size(); ++k) {
    const Stretch& s = stretches_[k];
    Line& line = lines[{s.judged.laneId, s.judged.side}];
    for (int b = 0; b < kBins; ++b) line.profile[b].road += profile[k][b].road, line.profile[b].painted += profile[k][b].painted;
    if (s.judged.firstFrame >= 0 && (line.firstFrame < 0 || s.judged.firstFrame < line.firstFrame)) line.firstFrame = s.judged.firstFrame;
    if (s.bestRuns > line.bestRuns) line.bestRuns = s.bestRuns, line.bestFrame = s.judged.bestFrame;
  }
  std::vector<LaneLineStretch> out;
  for (size_t k = 0; k < stretches_.size(); ++k) {
    if (std::none_of(profile[k].begin(), profile[k].end(), [](const PaintTally& t) { return t.road > 0; })) continue;
    LaneLineStretch j = stretches_[k].judged;
    const Line& line = lines.at({j.laneId, j.side});
    judge(line.profile, asphaltShare, j);
    j.firstFrame = line.firstFrame;
    j.bestFrame = line.bestFrame;
    out.push_back(std::move(j));
  }
  return out;
}

void LaneLineEvidence::judge(const Profile& line, double asphaltShare, LaneLineStretch& j) const {
  j.asphaltShare = asphaltShare;
  const auto window = [&](int b) { return PaintTally{line[b].road + line[b + 1].road, line[b].painted + line[b + 1].painted}; };
  const auto evidence = [&](const PaintTally& t) { return paintEvidence(t, asphaltShare, options_.laneLineContrast, 0.0); };
  j.onLine = window(kBins / 2 - 1);
  // The most painted half metre centred kMinOffset or more beside the line.
  double beside = -std::numeric_limits<double>::infinity();
  for (int b = 0; b + 1 < kBins; ++b) {
    const double centre = -kReach + (b + 1) * kBin;
    if (std::abs(centre) < kMinOffset) continue;
    const double e = evidence(window(b));
    if (e > beside) {
      beside = e;
      j.atOffset = window(b);
      const double lo = centre - kBin / 2, hi = centre + kBin / 2;  // the two bins' centres
      j.offset = j.atOffset.painted > 0 ? (line[b].painted * lo + line[b + 1].painted * hi) / j.atOffset.painted : centre;
    }
  }
  const double on = evidence(j.onLine);
  if (on >= options_.laneLineEvidence) {
    j.verdict = MapVerdict::Consistent;
    j.confidence = evidenceConfidence(on);
  } else if (beside >= options_.laneLineEvidence && on <= -options_.laneLineAsphalt) {
    j.verdict = MapVerdict::Contradicted;
    j.confidence = evidenceConfidence(std::min(beside, -on));
  }
}

}  // namespace hdprior
