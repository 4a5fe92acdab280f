#include "engine/changes/change_events.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

namespace hdprior {

namespace {

std::string areaDetail(const DrivableAreaVerdict& v, const std::vector<BoundaryStretch>& stretches) {
  // The most confident contradicted stretch says what the lidar saw; the count says how far it goes.
  const BoundaryStretch* best = nullptr;
  int count = 0;
  for (const BoundaryStretch& s : stretches) {
    if (s.areaId != v.id || s.verdict != MapVerdict::Contradicted) continue;
    ++count;
    if (!best || s.confidence > best->confidence) best = &s;
  }
  char b[200];
  if (!best) return "";
  char what[120];
  if (best->evidence == "polygon_offset")
    std::snprintf(what, sizeof what, "the whole area %.1f m off its kerbs (they lie x %+.1f, y %+.1f m from it)", best->polygonShift.norm(),
                  best->polygonShift.x(), best->polygonShift.y());
  else if (best->evidence == "road_across_gap")
    std::snprintf(what, sizeof what, "road across a %.1f m gap to the next area", best->offset);
  else
    std::snprintf(what, sizeof what, "kerb %.1f m %s its boundary", std::abs(best->offset), best->offset > 0 ? "outside" : "inside");
  std::snprintf(b, sizeof b, "drivable area %lld: %s, %d stretch%s (confidence %.2f)", (long long)v.id, what, count,
                count == 1 ? "" : "es", v.confidence);
  return b;
}

// "sweeps 263-368 left out (27 read): their kerbs meet the map shifted 4.0 m (first: 12 of 31 kerb points, 1
// unshifted); the poses look off", or for one sweep "sweep 300 left out: its kerbs ...; its pose looks off"
std::string misalignedDetail(const std::vector<MisalignedSweep>& sweeps, size_t first, size_t last) {
  const SweepAlignment& a = sweeps[first].alignment;
  char b[240];
  if (sweeps[first].offGround) {
    if (first == last)
      std::snprintf(b, sizeof b, "sweep %d left out: the road under it lies %.2f m %s the ground-height raster; its pose looks off",
                    sweeps[first].frame, std::abs(a.roadOverRaster), a.roadOverRaster > 0 ? "above" : "below");
    else
      std::snprintf(b, sizeof b, "sweeps %d-%d left out (%zu read): the road under them lies off the ground-height raster (first: %.2f m %s it); the poses look off",
                    sweeps[first].frame, sweeps[last].frame, last - first + 1, std::abs(a.roadOverRaster), a.roadOverRaster > 0 ? "above" : "below");
  } else if (first == last)
    std::snprintf(b, sizeof b, "sweep %d left out: its kerbs meet the map shifted %.1f m (%d of %d kerb points, %d unshifted); its pose looks off",
                  sweeps[first].frame, a.shift.norm(), a.alignedShifted, a.kerbs, a.alignedAtPose);
  else
    std::snprintf(b, sizeof b, "sweeps %d-%d left out (%zu read): their kerbs meet the map shifted %.1f m (first: %d of %d kerb points, %d unshifted); the poses look off",
                  sweeps[first].frame, sweeps[last].frame, last - first + 1, a.shift.norm(), a.alignedShifted, a.kerbs, a.alignedAtPose);
  return b;
}

}  // namespace

std::vector<RunEvent> mapChangeEvents(const MapChangeReport& report) {
  std::vector<RunEvent> events;
  for (const DrivableAreaVerdict& v : report.drivableAreas)
    if (v.verdict == MapVerdict::Contradicted && v.bestFrame >= 0)
      events.push_back({RunEvent::Kind::MapChange, 0, size_t(v.bestFrame), areaDetail(v, report.stretches)});
  for (const MissingSurface& m : report.missing) {
    if (m.bestFrame < 0) continue;
    char b[160];
    std::snprintf(b, sizeof b, "missing road surface %.0f m2, %.1f m beyond the map (confidence %.2f)", m.area, m.depth,
                  m.confidence);
    events.push_back({RunEvent::Kind::MapChange, 0, size_t(m.bestFrame), b});
  }
  for (const CrossingVerdict& c : report.crossings) {
    if (c.verdict != MapVerdict::Contradicted || c.bestFrame < 0) continue;
    char b[200];
    const CrossingBrightness& l = c.brightness;
    std::snprintf(b, sizeof b, "crossing %lld: no brighter than the road around it (%+.2f, %.1f times its uncertainty; the log's painted crossings %+.2f; confidence %.2f)",
                  (long long)c.id, l.lift(), l.z(), c.paintedLift, c.confidence);
    events.push_back({RunEvent::Kind::MapChange, 0, size_t(c.bestFrame), b});
  }
  for (const MissingCrossing& m : report.missingCrossings) {
    if (m.bestFrame < 0) continue;
    char b[160];
    std::snprintf(b, sizeof b, "unmapped crossing: paint in %d of %d road cells off the map's paint (confidence %.2f)", m.paintCells,
                  m.roadCells, m.confidence);
    events.push_back({RunEvent::Kind::MapChange, 0, size_t(m.bestFrame), b});
  }
  std::set<std::pair<int64_t, std::string>> lines;  // a line is judged whole: one event per line
  for (const LaneLineStretch& s : report.laneLines) {
    if (s.verdict != MapVerdict::Contradicted || s.bestFrame < 0 || !lines.insert({s.laneId, s.side}).second) continue;
    char b[240];
    std::snprintf(b, sizeof b, "lane %lld %s line: paint %.1f m to its %s (%d of %d road cells), as little on it as on the asphalt (%d of %d; confidence %.2f)",
                  (long long)s.laneId, s.side.c_str(), std::abs(s.offset), s.offset > 0 ? "left" : "right", s.atOffset.painted, s.atOffset.road,
                  s.onLine.painted, s.onLine.road, s.confidence);
    events.push_back({RunEvent::Kind::MapChange, 0, size_t(s.bestFrame), b});
  }
  for (size_t i = 0; i < report.misaligned.size(); ++i) {
    if (report.misaligned[i].followsAnother) continue;
    size_t last = i;
    while (last + 1 < report.misaligned.size() && report.misaligned[last + 1].followsAnother) ++last;
    events.push_back({RunEvent::Kind::MisalignedSweeps, 0, size_t(report.misaligned[i].frame),
                      misalignedDetail(report.misaligned, i, last)});
  }
  std::stable_sort(events.begin(), events.end(), [](const RunEvent& a, const RunEvent& b) { return a.frame < b.frame; });
  return events;
}

std::vector<RunEvent> mergedEvents(const std::vector<RunEvent>& run, const std::vector<RunEvent>& changes) {
  std::vector<RunEvent> out;
  std::merge(run.begin(), run.end(), changes.begin(), changes.end(), std::back_inserter(out),
             [](const RunEvent& a, const RunEvent& b) { return a.frame < b.frame; });
  return out;
}

}  // namespace hdprior
