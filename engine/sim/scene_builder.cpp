#include "engine/sim/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>
#include <unordered_set>

#include "engine/error.h"
#include "engine/map/boundary_distance.h"
#include "engine/map/drivable_raster.h"
#include "engine/sim/splitmix.h"
#include "engine/sim/traffic_islands.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

// Paint of a roadside's contrast and wear (without one: the default bright paint).
PaintOptions paintOptions(const std::optional<RoadsideOptions>& roadside, uint64_t seed) {
  PaintOptions paint;
  if (!roadside || !(roadside->paintContrast > 0.0)) return paint;
  const double white = std::clamp(roadside->roadReflectivity * roadside->paintContrast, 0.0, 255.0);
  paint.white = uint8_t(std::lround(white));
  paint.yellow = uint8_t(std::lround(0.8 * white));
  paint.wear = roadside->paintWear;
  paint.wearSeed = splitmix(seed ^ 0x3ea5ULL);
  return paint;
}

struct Region {
  Vec2 lo, hi;
  bool contains(const Vec2& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
};

VectorMap cropDrivable(const VectorMap& world, const Region& region) {
  VectorMap out;
  for (const DrivableArea& a : world.drivableAreas) {
    Vec2 lo = Vec2::Constant(1e300), hi = -lo;
    for (const Eigen::Vector3d& v : a.areaBoundary) {
      lo = lo.cwiseMin(v.head<2>());
      hi = hi.cwiseMax(v.head<2>());
    }
    if ((hi.array() >= region.lo.array()).all() && (lo.array() <= region.hi.array()).all())
      out.drivableAreas.push_back(a);
  }
  return out;
}

// Push-pull hole filling: NaN cells take the bilinear upsampling of a 2x coarser level
// (the mean of its valid children), recursively, so filled areas are smooth.
void fillHoles(std::vector<float>& h, int cols, int rows) {
  bool any = false, all = true;
  for (float v : h) {
    any |= !std::isnan(v);
    all &= !std::isnan(v);
  }
  if (all) return;
  if (!any) {
    std::fill(h.begin(), h.end(), 0.0f);
    return;
  }
  const int cc = (cols + 1) / 2, cr = (rows + 1) / 2;
  std::vector<float> coarse(size_t(cc) * size_t(cr), NAN);
  for (int r = 0; r < cr; ++r)
    for (int c = 0; c < cc; ++c) {
      double sum = 0.0;
      int n = 0;
      for (int dr = 0; dr < 2; ++dr)
        for (int dc = 0; dc < 2; ++dc) {
          const int x = 2 * c + dc, y = 2 * r + dr;
          if (x < cols && y < rows && !std::isnan(h[size_t(y) * size_t(cols) + size_t(x)])) {
            sum += h[size_t(y) * size_t(cols) + size_t(x)];
            ++n;
          }
        }
      if (n) coarse[size_t(r) * size_t(cc) + size_t(c)] = float(sum / n);
    }
  if (cc == cols && cr == rows) {  // 1x1: cannot coarsen further
    std::fill(h.begin(), h.end(), coarse[0]);
    return;
  }
  fillHoles(coarse, cc, cr);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      float& v = h[size_t(r) * size_t(cols) + size_t(c)];
      if (!std::isnan(v)) continue;
      // Fine cell centre in coarse cell coordinates (centres at +0.5).
      const double x = std::clamp((c + 0.5) / 2.0 - 0.5, 0.0, double(cc - 1));
      const double y = std::clamp((r + 0.5) / 2.0 - 0.5, 0.0, double(cr - 1));
      const int x0 = std::min(int(x), std::max(0, cc - 2)), y0 = std::min(int(y), std::max(0, cr - 2));
      const int x1 = std::min(x0 + 1, cc - 1), y1 = std::min(y0 + 1, cr - 1);
      const double fx = x - x0, fy = y - y0;
      const auto at = [&](int xx, int yy) { return double(coarse[size_t(yy) * size_t(cc) + size_t(xx)]); };
      v = float((1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1)));
    }
}

// The ground height resampled on a grid aligned with the raster's pixels (so values at
// pixel centres are the raster's own), NaN filled smoothly (push-pull).
std::pair<GridGeometry, std::vector<float>> groundGrid(const GroundHeight& ground, const Region& region) {
  const double res = 1.0 / ground.imgSim2City().s;
  const Vec2 t = ground.imgSim2City().t;
  GridGeometry g;
  g.resolution = res;
  g.origin = Vec2(std::floor((region.lo.x() + t.x()) / res) * res - t.x(), std::floor((region.lo.y() + t.y()) / res) * res - t.y());
  g.cols = int(std::ceil((region.hi.x() - g.origin.x()) / res)) + 1;
  g.rows = int(std::ceil((region.hi.y() - g.origin.y()) / res)) + 1;
  std::vector<float> h(g.cellCount());
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) h[g.index(c, r)] = float(ground.bilinearAt(g.cellCentre(c, r)));
  fillHoles(h, g.cols, g.rows);
  return {g, h};
}

// Coarse occupancy of object footprints, so objects do not overlap.
class Occupancy {
 public:
  explicit Occupancy(double cell) : cell_(cell) {}
  bool free(const std::vector<Vec2>& samples) const {
    for (const Vec2& p : samples)
      if (cells_.count(key(p))) return false;
    return true;
  }
  void mark(const std::vector<Vec2>& samples) {
    for (const Vec2& p : samples) cells_.insert(key(p));
  }

 private:
  int64_t key(const Vec2& p) const {
    return (int64_t(std::floor(p.x() / cell_)) << 32) ^ int64_t(uint32_t(int32_t(std::floor(p.y() / cell_))));
  }
  double cell_;
  std::unordered_set<int64_t> cells_;
};

// Points covering an oriented rectangle (every ~`step` metres, edges included).
std::vector<Vec2> footprint(const Vec2& centre, const Vec2& axis, const Vec2& half, double step) {
  const Vec2 side(-axis.y(), axis.x());
  const int nx = std::max(1, int(std::ceil(2 * half.x() / step))), ny = std::max(1, int(std::ceil(2 * half.y() / step)));
  std::vector<Vec2> out;
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j)
      out.push_back(centre + axis * (-half.x() + 2 * half.x() * i / nx) + side * (-half.y() + 2 * half.y() * j / ny));
  return out;
}

// Outward unit normal of the drivable boundary at p (towards the sidewalk); zero if unknown.
Vec2 curbNormal(const Scene& scene, const Vec2& p) {
  const double e = 0.3;
  const Vec2 g(scene.boundaryDistance(p + Vec2(e, 0)) - scene.boundaryDistance(p - Vec2(e, 0)),
               scene.boundaryDistance(p + Vec2(0, e)) - scene.boundaryDistance(p - Vec2(0, e)));
  return g.allFinite() && g.norm() > 1e-9 ? Vec2(g.normalized()) : Vec2(0, 0);
}

struct CurbPoint {
  Vec2 p, n;  // on the curb; outward normal
};

// Curb samples at least `spacing` apart among those facing the same way (so both sides of
// a narrow street get their own), in the raster's boundary order.
std::vector<CurbPoint> spacedCurbPoints(const DrivableRaster& raster, const Scene& scene, const Region& region,
                                        double spacing) {
  std::unordered_map<int64_t, std::vector<size_t>> cells;
  std::vector<CurbPoint> out;
  const auto key = [](int64_t cx, int64_t cy) { return (cx << 32) ^ int64_t(uint32_t(cy)); };
  for (const Vec2& p : raster.boundaryPoints()) {
    if (!region.contains(p)) continue;
    const Vec2 n = curbNormal(scene, p);
    const int64_t cx = int64_t(std::floor(p.x() / spacing)), cy = int64_t(std::floor(p.y() / spacing));
    bool near = false;
    for (int64_t dx = -1; dx <= 1 && !near; ++dx)
      for (int64_t dy = -1; dy <= 1 && !near; ++dy) {
        const auto it = cells.find(key(cx + dx, cy + dy));
        if (it == cells.end()) continue;
        for (size_t i : it->second)
          if ((out[i].p - p).norm() < spacing && out[i].n.dot(n) > 0.3) near = true;
      }
    if (near) continue;
    cells[key(cx, cy)].push_back(out.size());
    out.push_back({p, n});
  }
  return out;
}

double distanceToPath(const Vec2& p, std::span<const Vec2> path) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& q : path) best = std::min(best, (p - q).squaredNorm());
  return std::sqrt(best);
}

struct Placer {
  const Scene& scene;
  std::span<const Vec2> egoPath;
  std::mt19937_64& rng;
  Occupancy occupancy{1.0};

  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

  double minBoundary(const std::vector<Vec2>& pts) const {
    double m = std::numeric_limits<double>::infinity();
    for (const Vec2& p : pts) m = std::min(m, scene.boundaryDistance(p));
    return m;
  }
  double maxBoundary(const std::vector<Vec2>& pts) const {
    double m = -std::numeric_limits<double>::infinity();
    for (const Vec2& p : pts) m = std::max(m, scene.boundaryDistance(p));
    return m;
  }
  double minGround(const std::vector<Vec2>& pts) const {
    double m = std::numeric_limits<double>::infinity();
    for (const Vec2& p : pts) m = std::min(m, scene.groundHeight(p));
    return m;
  }
  double maxGround(const std::vector<Vec2>& pts) const {
    double m = -std::numeric_limits<double>::infinity();
    for (const Vec2& p : pts) m = std::max(m, scene.groundHeight(p));
    return m;
  }
  bool clearOfEgo(const std::vector<Vec2>& pts, double clearance) const {
    for (const Vec2& p : pts)
      if (distanceToPath(p, egoPath) < clearance) return false;
    return true;
  }
};

// Bushes and hedges on the sidewalks and the verge beyond, low planters on wide islands.
void placeVegetation(Scene& scene, const DrivableRaster& raster, const Region& region,
                     std::span<const TrafficIsland> islands, double density, Placer& placer) {
  for (const auto& [p, n] : spacedCurbPoints(raster, scene, region, 7.0)) {
    const bool want = placer.chance(density), hedge = placer.chance(0.4);
    if (!want) continue;
    const double sidewalk = scene.sidewalkWidthAt(p);
    const Vec2 axis(-n.y(), n.x());
    if (hedge) {
      const Vec2 half(placer.uniform(1.5, 5.0), placer.uniform(0.3, 0.6));
      const Vec2 centre = p + n * (sidewalk + half.y() + placer.uniform(0.0, 1.5));
      const auto fp = footprint(centre, axis, half, 0.5);
      const double height = placer.uniform(0.6, 1.5);
      if (placer.minBoundary(fp) < 0.5 || !placer.clearOfEgo(fp, 2.5) || !placer.occupancy.free(fp)) continue;
      placer.occupancy.mark(fp);
      const double z = placer.minGround(fp);
      scene.addBox({centre, std::atan2(axis.y(), axis.x()), half, z - 0.1, z + height, uint8_t(placer.uniform(20, 45))});
    } else {
      const double radius = placer.uniform(0.4, 1.0), height = placer.uniform(0.5, 1.5);
      const Vec2 centre = p + n * placer.uniform(std::max(1.0, 0.5 * sidewalk), sidewalk + 3.0);
      const auto fp = footprint(centre, Vec2(1, 0), Vec2(radius, radius), 0.5);
      if (placer.minBoundary(fp) < 0.3 || !placer.clearOfEgo(fp, 2.5) || !placer.occupancy.free(fp)) continue;
      placer.occupancy.mark(fp);
      const double z = scene.surfaceHeight(centre);
      scene.addCylinder({centre, radius, z - 0.1, z + height, uint8_t(placer.uniform(20, 45))});
    }
  }
  for (const TrafficIsland& t : islands) {
    const bool want = placer.chance(density);
    if (!want || t.radius < 0.7) continue;
    const Vec2 axis = (t.b - t.a).normalized(), centre = 0.5 * (t.a + t.b);
    const Vec2 half(0.5 * (t.b - t.a).norm(), t.radius - 0.3);
    const double z = scene.surfaceHeight(centre);
    scene.addBox({centre, std::atan2(axis.y(), axis.x()), half, z - 0.1, z + placer.uniform(0.3, 0.9),
                  uint8_t(placer.uniform(20, 45))});
  }
}

}  // namespace

Scene buildScene(const VectorMap& world, const GroundHeight& ground, const LaneGraph& lanes,
                 std::span<const Vec2> egoPath, int64_t startNs, const SceneOptions& options, uint64_t seed,
                 const std::string& source) {
  if (egoPath.empty()) throw Error(source, "empty drive");
  Region region{egoPath[0], egoPath[0]};
  for (const Vec2& p : egoPath) {
    region.lo = region.lo.cwiseMin(p);
    region.hi = region.hi.cwiseMax(p);
  }
  region.lo.array() -= options.margin;
  region.hi.array() += options.margin;

  const VectorMap cropped = cropDrivable(world, region);
  if (cropped.drivableAreas.empty()) throw Error(source, "no drivable area near the drive");
  DrivableRasterOptions ro;
  ro.resolution = options.rasterResolution;
  ro.margin = std::max(10.0, 2 * options.rasterResolution);
  const DrivableRaster raster = DrivableRaster::build(cropped, ro, source);
  auto [grid, heights] = groundGrid(ground, region);
  // Sparse ego path samples (every ~2 m) for clearance checks.
  std::vector<Vec2> path;
  for (const Vec2& p : egoPath)
    if (path.empty() || (p - path.back()).norm() > 2.0) path.push_back(p);
  BoundaryDistance mapDistance = BoundaryDistance::build(raster);
  std::vector<TrafficIsland> islands;
  if (options.roadside)
    islands = placeTrafficIslands(mapDistance, lanes, path, region.lo, region.hi, options.islandDensity, seed);
  Scene scene(grid, std::move(heights), std::move(mapDistance), options.sidewalkWidth, seed);
  if (options.roadside)
    scene.setRoadside(Roadside::build(*options.roadside, region.lo, region.hi, raster.boundaryPoints(), islands, seed));

  scene.setPaint(RoadPaint(world, region.lo, region.hi, paintOptions(options.roadside, seed)));

  std::mt19937_64 rng(seed ^ 0x5ce4e5eedULL);
  Placer placer{scene, path, rng};
  // Scene families draw from their own generator, so the default scene stays as it was.
  std::mt19937_64 familyRng(seed ^ 0xfa3117ULL);
  const double densityAngle = std::uniform_real_distribution<double>(0.0, 6.283185307179586)(familyRng);
  const double densityPhase = std::uniform_real_distribution<double>(0.0, 6.283185307179586)(familyRng);
  const Vec2 densityK = Vec2(std::cos(densityAngle), std::sin(densityAngle)) * (6.283185307179586 / 350.0);
  const auto buildingDensityAt = [&](const Vec2& p) {
    if (options.buildingDensityVariation <= 0.0) return options.buildingDensity;
    const double swing = options.buildingDensityVariation * std::sin(densityK.dot(p) + densityPhase);
    return std::clamp(options.buildingDensity * (1.0 + swing), 0.0, 1.0);
  };

  // Junctions (intersection lanes, 4 m cells): no parking there.
  std::unordered_set<int64_t> junction;
  const auto cellKey = [](const Vec2& p, int dx, int dy) {
    return (int64_t(std::floor(p.x() / 4.0) + dx) << 32) ^ int64_t(uint32_t(int32_t(std::floor(p.y() / 4.0) + dy)));
  };
  for (const Lane& lane : lanes.lanes())
    if (lane.isIntersection)
      for (const Eigen::Vector3d& q : lane.centerline)
        if (region.contains(q.head<2>())) junction.insert(cellKey(q.head<2>(), 0, 0));
  const auto nearJunction = [&](const Vec2& p) {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if (junction.count(cellKey(p, dx, dy))) return true;
    return false;
  };

  // Parked cars: just inside the curb, along it, never near the drive nor in junctions.
  for (const auto& [p, n] : spacedCurbPoints(raster, scene, region, 6.5)) {
    const bool want = placer.chance(options.parked);
    if (!want) continue;
    const Vec2 axis(-n.y(), n.x()), half(2.3, 0.95);
    const Vec2 centre = p - n * 1.15;
    const auto fp = footprint(centre, axis, half, 0.8);
    if (nearJunction(centre) || placer.maxBoundary(fp) > -0.05 || !placer.clearOfEgo(fp, 2.5) || !placer.occupancy.free(fp)) continue;
    placer.occupancy.mark(fp);
    const double z = placer.minGround(fp);
    const double height = placer.uniform(1.4, 1.9);
    scene.addBox({centre, std::atan2(axis.y(), axis.x()) + placer.uniform(-0.04, 0.04), half, z + 0.25,
                  z + height, uint8_t(placer.uniform(40, 110))});
  }

  // Poles and trees on the sidewalk.
  for (const auto& [p, n] : spacedCurbPoints(raster, scene, region, options.poleSpacing)) {
    const Vec2 c = p + n * 0.6;
    if (scene.boundaryDistance(c) < 0.3 || !placer.clearOfEgo({c}, 2.5) || !placer.occupancy.free({c})) continue;
    placer.occupancy.mark({c});
    const double z = scene.surfaceHeight(c);
    scene.addCylinder({c, 0.12, z - 0.2, z + placer.uniform(6.0, 9.0), 90});
  }
  for (const auto& [p, n] : spacedCurbPoints(raster, scene, region, 9.0)) {
    const bool want = placer.chance(options.treeDensity);
    if (!want) continue;
    const Vec2 c = p + n * placer.uniform(1.5, 2.5);
    const double crown = placer.uniform(1.2, 2.4);
    const auto fp = footprint(c, Vec2(1, 0), Vec2(crown, crown), 1.0);
    if (scene.boundaryDistance(c) < 1.0 || !placer.clearOfEgo(fp, 2.5) || !placer.occupancy.free({c})) continue;
    placer.occupancy.mark({c});
    const double z = scene.surfaceHeight(c);
    const double trunk = placer.uniform(2.2, 3.2);
    scene.addCylinder({c, 0.18, z - 0.2, z + trunk + 0.3, 35});
    scene.addCylinder({c, crown, z + trunk, z + trunk + placer.uniform(2.5, 5.0), 25});
  }

  // Buildings: facades parallel to the curb, behind the sidewalk at varying setbacks, with gaps.
  for (const auto& [p, n] : spacedCurbPoints(raster, scene, region, 14.0)) {
    const bool want = placer.chance(buildingDensityAt(p));
    if (!want) continue;

    const Vec2 axis(-n.y(), n.x());
    const Vec2 half(placer.uniform(5.0, 14.0), placer.uniform(4.0, 9.0));
    const double sidewalk = scene.sidewalkWidthAt(p);
    const double setback = sidewalk - 0.5 + placer.uniform(0.0, 6.0);
    const Vec2 centre = p + n * (setback + half.y());
    const auto fp = footprint(centre, axis, half, 1.0);
    if (placer.minBoundary(fp) < sidewalk - 1.0 || !placer.clearOfEgo(fp, 5.0) ||
        !placer.occupancy.free(fp))
      continue;
    placer.occupancy.mark(fp);
    const double z = placer.minGround(fp) - 1.0;
    const double top = placer.maxGround(fp) + placer.uniform(4.0, 24.0);
    scene.addBox({centre, std::atan2(axis.y(), axis.x()), half, z, top, uint8_t(placer.uniform(30, 90))});
  }

  if (options.vegetationDensity > 0.0) {
    Placer family{scene, path, familyRng, placer.occupancy};
    placeVegetation(scene, raster, region, islands, options.vegetationDensity, family);
  }

  // Moving cars on random lane routes.
  std::vector<size_t> candidates;
  for (size_t i = 0; i < lanes.lanes().size(); ++i) {
    const Lane& lane = lanes.lanes()[i];
    if (!lane.isIntersection && !lane.centerline.empty() && region.contains(lane.centerline.front().head<2>()))
      candidates.push_back(i);
  }
  for (int k = 0; k < options.movingCars && !candidates.empty(); ++k) {
    const size_t start = candidates[std::uniform_int_distribution<size_t>(0, candidates.size() - 1)(rng)];
    const std::vector<size_t> route = lanes.randomRoute(start, 600.0, rng);
    const Polyline3 line = lanes.routeCenterline(route);
    const double length = polylineLength(line);
    if (length < 20.0) continue;
    MovingCar car;
    for (const Eigen::Vector3d& q : resampleByArcLength(line, size_t(length) + 1)) car.path.push_back(q.head<2>());
    car.speed = placer.uniform(4.0, 11.0);
    car.startS = placer.uniform(0.0, std::min(60.0, length));
    car.startNs = startNs;
    car.height = placer.uniform(1.4, 1.9);
    scene.addMovingCar(std::move(car));
  }
  scene.index();
  return scene;
}

}  // namespace hdprior
