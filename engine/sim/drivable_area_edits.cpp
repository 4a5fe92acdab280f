#include "engine/sim/drivable_area_edits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/sim/boundary_edit.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;
using Kind = MapChange::Kind;

double uniform(EditContext& c, double a, double b) { return std::uniform_real_distribution<double>(a, b)(c.rng); }

bool nearDrive(const EditContext& c, std::span<const Vec2> geometry, bool closed) {
  return std::isinf(c.withinM) || polylineDistance(c.drive, geometry, closed) <= c.withinM;
}

// The ring in 3-D, each vertex at the height of the area's nearest vertex.
Polyline3 lifted(const Ring2& ring, const Polyline3& like) {
  Polyline3 out;
  for (const Vec2& p : ring) {
    const auto nearest = std::min_element(like.begin(), like.end(), [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return (a.head<2>() - p).squaredNorm() < (b.head<2>() - p).squaredNorm();
    });
    out.emplace_back(p.x(), p.y(), nearest->z());
  }
  return out;
}

std::optional<MapChange> shifted(const Ring2& ring, EditContext& c, DrivableArea& written) {
  const double angle = uniform(c, 0.0, 2 * std::numbers::pi), dist = uniform(c, 1.0, 3.0);
  MapChange change;
  change.shift = Vec2(dist * std::cos(angle), dist * std::sin(angle));
  for (Eigen::Vector3d& v : written.areaBoundary) v.head<2>() += change.shift;
  for (const Vec2& p : ring) change.mapOutline.push_back(p + change.shift);
  return change;
}

// An 8 m x 15 m strip reaching outwards from a vertex (near the drive), on no road of the world.
std::optional<MapChange> added(const Ring2& ring, const DrivableArea& area, EditContext& c, DrivableArea& written) {
  const size_t n = ring.size();
  const double orientation = signedArea(ring) > 0.0 ? 1.0 : -1.0;
  std::vector<size_t> vertices;
  for (size_t k = 0; k < n; ++k)
    if (nearDrive(c, std::span(&ring[k], 1), false)) vertices.push_back(k);
  std::shuffle(vertices.begin(), vertices.end(), c.rng);
  for (const size_t k : vertices) {
    const Vec2 base = ring[k];
    const Vec2 bisector = -orientation * (leftNormal(ring[(k + n - 1) % n], base) + leftNormal(base, ring[(k + 1) % n]));
    if (bisector.norm() < 1e-6) continue;
    const Vec2 u = bisector.normalized(), w(-u.y(), u.x());
    bool clear = true;
    for (double along = 1.0; along <= 15.0 && clear; along += 1.0)
      for (double across = -4.0; across <= 4.0 && clear; across += 1.0) clear = !c.world.contains(base + along * u + across * w);
    if (!clear) continue;
    MapChange change;
    change.mapOutline = {base - 4.0 * w, base + 4.0 * w, base + 4.0 * w + 15.0 * u, base - 4.0 * w + 15.0 * u};
    written.areaBoundary.clear();
    for (const Vec2& p : change.mapOutline) written.areaBoundary.emplace_back(p.x(), p.y(), area.areaBoundary[0].z());
    return change;
  }
  return std::nullopt;
}

// Sides worth editing: at least `minLength` long and near the drive, longest first.
std::vector<RingSide> candidateSides(const Ring2& ring, double minLength, EditContext& c) {
  std::vector<std::pair<double, RingSide>> sides;
  for (const RingSide& s : ringSides(ring)) {
    const Ring2 v = sideVertices(ring, s);
    if (const double length = polylineLength2(v); length >= minLength && nearDrive(c, v, false)) sides.push_back({length, s});
  }
  std::shuffle(sides.begin(), sides.end(), c.rng);
  // The long sides (a street's kerbs, not its ends) first, in random order among themselves.
  double longest = 0.0;
  for (const auto& s : sides) longest = std::max(longest, s.first);
  std::stable_partition(sides.begin(), sides.end(), [&](const auto& s) { return s.first >= 0.5 * longest; });
  std::vector<RingSide> out;
  for (const auto& s : sides) out.push_back(s.second);
  return out;
}

MapChange fromEdit(BoundaryEdit edit, double offset, const DrivableArea& area, DrivableArea& written) {
  MapChange change;
  change.mapOutline = edit.ring;
  change.changedStretch = std::move(edit.stretch);
  change.worldStretch = std::move(edit.worldStretch);
  change.offsetM = offset;
  written.areaBoundary = lifted(edit.ring, area.areaBoundary);
  if ((area.areaBoundary.front() - area.areaBoundary.back()).norm() < 1e-9)
    written.areaBoundary.push_back(written.areaBoundary.front());  // closed as the world's was
  return change;
}

std::optional<MapChange> narrowed(const Ring2& ring, const DrivableArea& area, EditContext& c, DrivableArea& written) {
  const double inset = uniform(c, 1.0, 2.5);
  for (const RingSide& side : candidateSides(ring, 5.0, c))
    if (auto edit = narrowSide(ring, side, inset)) return fromEdit(std::move(*edit), -inset, area, written);
  return std::nullopt;
}

std::optional<MapChange> kerbMoved(const Ring2& ring, const DrivableArea& area, EditContext& c, DrivableArea& written) {
  const double wanted = uniform(c, 10.0, 25.0), offset = (uniform(c, 0.0, 1.0) < 0.5 ? -1.0 : 1.0) * uniform(c, 1.0, 3.0);
  for (const RingSide& side : candidateSides(ring, 10.0, c)) {
    const Ring2 v = sideVertices(ring, side);
    const double length = std::min(wanted, polylineLength2(v));
    // The stretch's middle at a metre of the side near the drive.
    std::vector<double> middles;
    double s = 0.0;
    for (size_t k = 0; k + 1 < v.size(); ++k) {
      const double edge = (v[k + 1] - v[k]).norm();
      for (double x = std::ceil(s) - s; x < edge; x += 1.0) {
        const Vec2 p = v[k] + x / edge * (v[k + 1] - v[k]);
        if (nearDrive(c, std::span(&p, 1), false)) middles.push_back(s + x);
      }
      s += edge;
    }
    if (middles.empty()) continue;
    const double middle = middles[std::uniform_int_distribution<size_t>(0, middles.size() - 1)(c.rng)];
    const double s0 = std::clamp(middle - 0.5 * length, 0.0, s - length);
    if (auto edit = moveKerbStretch(ring, side, s0, length, offset, 3.0)) return fromEdit(std::move(*edit), offset, area, written);
  }
  return std::nullopt;
}

}  // namespace

std::optional<MapChange> editDrivableArea(Kind kind, const DrivableArea& area, int64_t newId, EditContext& context,
                                          DrivableArea& written) {
  const Ring2 ring = ringOf(area.areaBoundary);
  std::optional<MapChange> change;
  written = area;
  if (kind == Kind::Removed) change = MapChange{};
  else if (kind == Kind::Shifted) change = shifted(ring, context, written);
  else if (kind == Kind::Added) change = added(ring, area, context, written);
  else if (kind == Kind::Narrowed) change = narrowed(ring, area, context, written);
  else if (kind == Kind::KerbMoved) change = kerbMoved(ring, area, context, written);
  if (!change) return std::nullopt;
  change->kind = kind;
  change->id = kind == Kind::Added ? newId : area.id;
  written.id = change->id;
  if (kind != Kind::Added) change->worldOutline = ring;
  return change;
}

}  // namespace hdprior
