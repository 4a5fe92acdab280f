#include "engine/sim/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hdprior {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Slab test against a box in its own frame; updates best (range) and hit.
void hitBox(const SceneBox& b, const Eigen::Vector2d& yawAxis, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
            double& best, RayHit& hit) {
  const double c = yawAxis.x(), s = yawAxis.y();
  const Eigen::Vector2d rel = o.head<2>() - b.centre;
  const double lo[3] = {c * rel.x() + s * rel.y(), -s * rel.x() + c * rel.y(), o.z()};
  const double ld[3] = {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
  const double mn[3] = {-b.halfSize.x(), -b.halfSize.y(), b.zMin}, mx[3] = {b.halfSize.x(), b.halfSize.y(), b.zMax};
  double tNear = 0.0, tFar = best;
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(ld[k]) < 1e-12) {
      if (lo[k] < mn[k] || lo[k] > mx[k]) return;
      continue;
    }
    double t0 = (mn[k] - lo[k]) / ld[k], t1 = (mx[k] - lo[k]) / ld[k];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tNear) {
      tNear = t0;
      axis = k;
    }
    tFar = std::min(tFar, t1);
    if (tNear > tFar) return;
  }
  if (axis < 0 || tNear >= best) return;  // origin inside the box: no return
  best = tNear;
  hit = {tNear, PointLabel::Object, std::abs(ld[axis]), b.reflectivity};
}

// False when the ray cannot reach the box: its horizontal path misses the circle around the box's
// footprint, or meets it only behind the origin or beyond `best`. A cheap test before hitBox, which
// needs the box's axes (a sine and a cosine per moving box and ray).
bool mayHitBox(const SceneBox& b, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double best) {
  const Eigen::Vector2d rel = b.centre - o.head<2>(), h = d.head<2>();
  const double r2 = b.halfSize.squaredNorm() * (1.0 + 1e-9) + 1e-12;
  const double h2 = h.squaredNorm();
  if (h2 < 1e-18) return rel.squaredNorm() <= r2;
  const double along = rel.dot(h);
  const double perp2 = rel.squaredNorm() - along * along / h2;
  if (perp2 > r2) return false;
  const double half = std::sqrt((r2 - perp2) / h2), mid = along / h2;  // the circle's chord in t
  return mid + half >= 0.0 && mid - half <= best;
}

void hitCylinder(const SceneCylinder& cy, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double& best,
                 RayHit& hit) {
  const Eigen::Vector2d rel = o.head<2>() - cy.centre;
  const double a = d.x() * d.x() + d.y() * d.y();
  const double b = rel.dot(d.head<2>()), c = rel.squaredNorm() - cy.radius * cy.radius;
  // Side wall.
  if (a > 1e-12) {
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double t = (-b - std::sqrt(disc)) / a;
      if (t > 0.0 && t < best) {
        const double z = o.z() + t * d.z();
        if (z >= cy.zMin && z <= cy.zMax) {
          const Eigen::Vector2d n = (rel + t * d.head<2>()) / cy.radius;
          best = t;
          hit = {t, PointLabel::Object, std::abs(n.dot(d.head<2>())), cy.reflectivity};
          return;
        }
      }
    }
  }
  // Caps.
  if (std::abs(d.z()) > 1e-12) {
    const double zc = d.z() < 0.0 ? cy.zMax : cy.zMin;
    const double t = (zc - o.z()) / d.z();
    if (t > 0.0 && t < best && (rel + t * d.head<2>()).squaredNorm() <= cy.radius * cy.radius) {
      best = t;
      hit = {t, PointLabel::Object, std::abs(d.z()), cy.reflectivity};
    }
  }
}

}  // namespace

std::optional<RayHit> castRayObjects(const Scene& scene, std::span<const SceneBox> moving,
                                     const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double maxRange) {
  double best = maxRange;
  RayHit hit;
  bool found = false;
  for (const SceneBox& b : moving) {
    if (!mayHitBox(b, origin, dir, best)) continue;
    const double before = best;
    hitBox(b, Eigen::Vector2d(std::cos(b.yaw), std::sin(b.yaw)), origin, dir, best, hit);
    found |= best < before;
  }
  const GridGeometry& g = scene.objectGrid();
  if (g.cols <= 0 || scene.boxes().size() + scene.cylinders().size() == 0) {
    if (found) return hit;
    return std::nullopt;
  }
  // 2-D DDA over the object grid, from the ray's entry into the grid.
  const Eigen::Vector2d dxy = dir.head<2>();
  const double horiz = dxy.norm();
  Eigen::Vector2d p = g.toCell(origin.head<2>());
  double tEnter = 0.0;
  const double lenX = g.cols, lenY = g.rows;
  {
    // Clip [0, best] to the grid box.
    double t0 = 0.0, t1 = best;
    const double pc[2] = {p.x(), p.y()}, dc[2] = {dxy.x() / g.resolution, dxy.y() / g.resolution};
    const double hiC[2] = {lenX, lenY};
    for (int k = 0; k < 2; ++k) {
      if (std::abs(dc[k]) < 1e-15) {
        if (pc[k] < 0.0 || pc[k] >= hiC[k]) return found ? std::optional<RayHit>(hit) : std::nullopt;
        continue;
      }
      double a = (0.0 - pc[k]) / dc[k], b = (hiC[k] - pc[k]) / dc[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    if (t0 > t1 || horiz < 1e-9) {
      // Vertical rays or rays missing the grid: only the origin's cell could matter.
      if (horiz < 1e-9 && t0 <= t1) tEnter = 0.0;
      else return found ? std::optional<RayHit>(hit) : std::nullopt;
    }
    tEnter = t0;
  }
  const Eigen::Vector2d pe = p + tEnter * dxy / g.resolution;
  int col = std::clamp(int(std::floor(pe.x())), 0, g.cols - 1), row = std::clamp(int(std::floor(pe.y())), 0, g.rows - 1);
  const int stepC = dxy.x() > 0 ? 1 : -1, stepR = dxy.y() > 0 ? 1 : -1;
  const double invX = std::abs(dxy.x()) > 1e-15 ? g.resolution / std::abs(dxy.x()) : kInf;
  const double invY = std::abs(dxy.y()) > 1e-15 ? g.resolution / std::abs(dxy.y()) : kInf;
  double tNextX = std::abs(dxy.x()) > 1e-15
                      ? tEnter + ((stepC > 0 ? col + 1 - pe.x() : pe.x() - col) * invX)
                      : kInf;
  double tNextY = std::abs(dxy.y()) > 1e-15
                      ? tEnter + ((stepR > 0 ? row + 1 - pe.y() : pe.y() - row) * invY)
                      : kInf;
  const auto& boxes = scene.boxes();
  if (scene.boxAxes().size() != boxes.size()) throw std::logic_error("Scene::index() was not called");
  const auto& cylinders = scene.cylinders();
  while (true) {
    for (const uint32_t item : scene.cellItems(col, row)) {
      const double before = best;
      if (item & Scene::kCylinderBit) hitCylinder(cylinders[item & ~Scene::kCylinderBit], origin, dir, best, hit);
      else hitBox(boxes[item], scene.boxAxes()[item], origin, dir, best, hit);
      found |= best < before;
    }
    const double tNext = std::min(tNextX, tNextY);
    if (tNext >= best) break;
    if (tNextX < tNextY) {
      col += stepC;
      tNextX += invX;
    } else {
      row += stepR;
      tNextY += invY;
    }
    if (col < 0 || row < 0 || col >= g.cols || row >= g.rows) break;
  }
  if (found) return hit;
  return std::nullopt;
}

std::optional<RayHit> castRayGround(const Scene& scene, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                    double maxRange) {
  const double horiz = dir.head<2>().norm();
  // Bounds of how fast the height above the surface can fall along the ray: anywhere, above the
  // envelope (the ground plus the highest rise), and on the road (where steps stop at the kerb).
  const double lipschitz = std::abs(dir.z()) + scene.maxSlope() * horiz;
  const double envelopeLipschitz = std::abs(dir.z()) + scene.groundSlope() * horiz;
  const double roadLipschitz = std::abs(dir.z()) + scene.roadSlope() * horiz;
  // The physical kerb's distance field is not quite 1-Lipschitz where a roadside moves it.
  const double kerbReach = scene.roadside() ? 1.0 / 1.15 : 1.0;
  const double maxRise = scene.maxRise();  // the surface never rises more above the ground (0.2 m curbs)
  const bool roadside = scene.roadside() != nullptr;
  // Height of the ray above the surface at t, where the ground height is g; also reports the
  // boundary distance there.
  const auto aboveOver = [&](double t, double g, double& boundary) {
    const Eigen::Vector3d p = origin + t * dir;
    const Eigen::Vector2d xy = p.head<2>();
    if (roadside) {
      const Scene::SurfacePoint s = scene.surfacePoint(xy);
      boundary = s.boundary;
      return p.z() - g - s.rise;
    }
    boundary = scene.boundaryDistance(xy);
    return boundary < 0.0 ? p.z() - g : p.z() - g - scene.curbHeight(xy);
  };
  const auto above = [&](double t, double& boundary) {
    return aboveOver(t, scene.groundHeight((origin + t * dir).head<2>()), boundary);
  };
  double t = 0.0, boundary = 0.0, tPrev = 0.0;
  if (above(t, boundary) <= 0.0) return std::nullopt;  // origin under the ground
  while (true) {
    const Eigen::Vector3d p = origin + t * dir;
    // Far above the highest the surface can be here: a cheap step on the ground alone.
    const double ground = scene.groundHeight(p.head<2>());
    const double overEnvelope = p.z() - ground - maxRise;
    double step;
    if (overEnvelope > 0.05) {
      step = overEnvelope / envelopeLipschitz;
    } else {
      const double h = aboveOver(t, ground, boundary);
      if (h <= 0.0) break;
      // A step that cannot cross the surface, nor run into a curb while within its height.
      step = h / (boundary < 0.0 ? roadLipschitz : lipschitz);
      if (boundary < 0.0 && horiz > 1e-9) step = std::min(step, std::max(-boundary * kerbReach, 0.02) / horiz);
    }
    // Moving up faster than the surface can rise: no hit.
    if (dir.z() > scene.maxSlope() * horiz) return std::nullopt;
    tPrev = t;
    t += std::max(step, std::max(0.01, 0.002 * t));
    if (t > maxRange) return std::nullopt;
  }
  // Bisection between tPrev (above) and t (below).
  double a = tPrev, b = t;
  for (int i = 0; i < 20 && b - a > 1e-4; ++i) {
    const double m = 0.5 * (a + b);
    double bm = 0.0;
    if (above(m, bm) > 0.0) a = m;
    else b = m;
  }
  double prevBoundary = 0.0, hitBoundary = 0.0;
  const double hPrev = above(a, prevBoundary);
  above(b, hitBoundary);
  RayHit hit;
  hit.range = b;
  const bool curbFace = prevBoundary < 0.0 && hitBoundary >= 0.0 && hPrev > 0.0 && hPrev < maxRise + 0.05 &&
                        b - a < 0.05;
  const double sidewalk = roadside ? scene.sidewalkWidthAt((origin + b * dir).head<2>()) : scene.sidewalkWidth();
  hit.label = hitBoundary < 0.0        ? PointLabel::Road
              : hitBoundary < sidewalk ? PointLabel::SidewalkCurb
                                       : PointLabel::OtherGround;
  hit.reflectivity = scene.reflectivity(hit.label);
  if (hit.label == PointLabel::Road) {
    const Eigen::Vector2d at = (origin + b * dir).head<2>();
    const uint8_t paint = scene.paint().reflectivityAt(at);
    hit.reflectivity = paint ? paint : scene.roadReflectivityAt(at);
  }
  hit.cosIncidence = curbFace ? horiz : std::abs(dir.z());
  return hit;
}

std::optional<RayHit> castRay(const Scene& scene, std::span<const SceneBox> moving, const Eigen::Vector3d& origin,
                              const Eigen::Vector3d& dir, double maxRange) {
  const auto object = castRayObjects(scene, moving, origin, dir, maxRange);
  const auto ground = castRayGround(scene, origin, dir, object ? object->range : maxRange);
  if (ground) return ground;
  return object;
}

}  // namespace hdprior
