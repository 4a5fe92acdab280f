#include "engine/eval/change_scoring.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "engine/geom/polygon2d.h"

namespace hdprior {

namespace {

using Line = std::vector<Eigen::Vector2d>;

// The nearest distance between two lines, 0 where a point of one lies inside the other (a polygon).
double distance(const Line& a, bool aClosed, const Line& b, bool bClosed) {
  if (aClosed && !b.empty() && ringContains(a, b.front())) return 0.0;
  if (bClosed && !a.empty() && ringContains(b, a.front())) return 0.0;
  Line aLine = a;
  if (aClosed && a.size() > 2) aLine.push_back(a.front());
  return polylineDistance(aLine, b, bClosed);
}

struct Place {
  Line line;
  bool closed = false;
};

// Where each report of an element lies: a contradicted area's contradicted stretches, a missing
// surface's outline; a contradicted or missing crossing's outline; a lane line's contradicted
// stretches.
std::vector<std::vector<Place>> reportPlaces(const MapChangeReport& report, MapElement element) {
  std::vector<std::vector<Place>> out;
  if (element == MapElement::LaneBoundary) {
    std::map<std::pair<int64_t, std::string>, std::vector<Place>> byLine;
    for (const LaneLineStretch& s : report.laneLines)
      if (s.verdict == MapVerdict::Contradicted) byLine[{s.laneId, s.side}].push_back({s.line, false});
    for (auto& [line, places] : byLine) out.push_back(std::move(places));
    return out;
  }
  if (element == MapElement::PedestrianCrossing) {
    for (const CrossingVerdict& c : report.crossings)
      if (c.verdict == MapVerdict::Contradicted) out.push_back({{c.outline, true}});
    for (const MissingCrossing& m : report.missingCrossings) out.push_back({{m.outline, true}});
    return out;
  }
  for (const DrivableAreaVerdict& v : report.drivableAreas) {
    if (v.verdict != MapVerdict::Contradicted) continue;
    std::vector<Place> places;
    for (const BoundaryStretch& s : report.stretches)
      if (s.areaId == v.id && s.verdict == MapVerdict::Contradicted) places.push_back({s.line, false});
    out.push_back(std::move(places));
  }
  for (const MissingSurface& m : report.missing) out.push_back({{m.outline, true}});
  return out;
}

std::vector<Place> labelPlaces(const MapChangeLabel& l) {
  std::vector<Place> out;
  for (const Line& line : l.places) out.push_back({line, !l.openLine()});
  return out;
}

bool near(const std::vector<Place>& a, const std::vector<Place>& b, double match) {
  for (const Place& p : a)
    for (const Place& q : b)
      if (distance(p.line, p.closed, q.line, q.closed) <= match) return true;
  return false;
}

}  // namespace

namespace {

nlohmann::json scoreJson(const ChangeScore& s) {
  const auto value = [](double v) { return std::isfinite(v) ? nlohmann::json(std::round(v * 1e4) / 1e4) : nlohmann::json(nullptr); };
  return {{"reports", s.reports},
          {"reports_near_change", s.reportsNearChange},
          {"precision", value(s.precision())},
          {"changes", s.changes},
          {"changes_found", s.changesFound},
          {"recall", value(s.recall())},
          {"driven_km", value(s.drivenKm)},
          {"false_alarms_per_km", value(s.drivenKm > 0 ? double(s.falseAlarms()) / s.drivenKm : NAN)}};
}

}  // namespace

std::string changeScoreJson(const MapCheckScore& score) {
  nlohmann::json j = scoreJson(score.drivableAreas);
  j["pedestrian_crossing"] = scoreJson(score.crossings);
  j["lane_boundary"] = scoreJson(score.laneLines);
  return j.dump(2) + "\n";
}

std::string changeScoreLine(const MapCheckScore& score) {
  std::string line;
  for (const auto& [name, s] : {std::pair{"drivable areas", &score.drivableAreas}, {"crossings", &score.crossings}, {"lane lines", &score.laneLines}}) {
    char b[160];
    std::snprintf(b, sizeof b, "%s%s %zu of %zu reports near a change, %zu of %zu changes found", line.empty() ? "" : "; ", name,
                  s->reportsNearChange, s->reports, s->changesFound, s->changes);
    line += b;
  }
  return line;
}

MapCheckScore scoreMapCheck(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels) {
  return {scoreMapChanges(report, labels, MapElement::DrivableArea), scoreMapChanges(report, labels, MapElement::PedestrianCrossing),
          scoreMapChanges(report, labels, MapElement::LaneBoundary)};
}

ChangeScore& ChangeScore::operator+=(const ChangeScore& o) {
  reports += o.reports, reportsNearChange += o.reportsNearChange;
  changes += o.changes, changesFound += o.changesFound;
  drivenKm += o.drivenKm;
  return *this;
}

namespace {

MapElement elementOf(const MapChangeLabel& l) {
  return l.element == "drivable_area" ? MapElement::DrivableArea
         : l.element == "pedestrian_crossing" ? MapElement::PedestrianCrossing
                                              : MapElement::LaneBoundary;
}

}  // namespace

std::vector<size_t> missedChanges(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels, double nearRoute,
                                  double match) {
  std::map<MapElement, std::vector<std::vector<Place>>> byElement;
  for (MapElement e : {MapElement::DrivableArea, MapElement::PedestrianCrossing, MapElement::LaneBoundary})
    byElement[e] = reportPlaces(report, e);
  std::vector<size_t> out;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i].routeDistance > nearRoute) continue;
    const std::vector<Place> changed = labelPlaces(labels[i]);
    const std::vector<std::vector<Place>>& reports = byElement.at(elementOf(labels[i]));
    if (std::none_of(reports.begin(), reports.end(), [&](const auto& r) { return near(r, changed, match); })) out.push_back(i);
  }
  return out;
}

ChangeScore scoreMapChanges(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels, MapElement element,
                            double nearRoute, double match) {
  ChangeScore score;
  score.drivenKm = report.drivenKm;
  std::vector<std::vector<Place>> changed;
  std::vector<bool> passed;
  for (const MapChangeLabel& l : labels) {
    if (elementOf(l) != element) continue;
    changed.push_back(labelPlaces(l));
    passed.push_back(l.routeDistance <= nearRoute);
  }
  const std::vector<std::vector<Place>> reports = reportPlaces(report, element);
  score.reports = reports.size();
  for (const std::vector<Place>& r : reports)
    score.reportsNearChange += std::any_of(changed.begin(), changed.end(), [&](const auto& c) { return near(r, c, match); });
  for (size_t i = 0; i < changed.size(); ++i) {
    if (!passed[i]) continue;
    ++score.changes;
    score.changesFound += std::any_of(reports.begin(), reports.end(), [&](const auto& r) { return near(r, changed[i], match); });
  }
  return score;
}

}  // namespace hdprior
