// The drivable raster: union of the drivable-area polygons, on synthetic shapes with known
// areas and on the real map against Boost.Geometry's exact polygon union.
#include "engine/map/drivable_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

// Boost.Geometry's rescaling policy trips GCC 12's -Wmaybe-uninitialized in its own code.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>

#include "engine/error.h"
#include "engine/io/vector_map.h"
#include "engine/map/boundary_distance.h"
#include "synthetic_maps.h"
#include "test_data.h"

namespace hdprior {
namespace {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;
using BMultiPolygon = bg::model::multi_polygon<BPolygon>;

using test::mapOf;
using test::rectangle;
using test::ring;

std::filesystem::path realVectorMap() {
  for (const auto& e : std::filesystem::directory_iterator(test::sharedLog() / "map")) {
    if (e.path().filename().string().starts_with("log_map_archive_")) return e.path();
  }
  throw std::runtime_error("no vector map in the shared log");
}

BPolygon toBoost(const Polyline3& r) {
  BPolygon p;
  for (const Eigen::Vector3d& v : r) bg::append(p.outer(), BPoint(v.x(), v.y()));
  bg::correct(p);
  return p;
}

double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

DrivableRaster build(const VectorMap& map, double resolution = 0.1) {
  return DrivableRaster::build(map, {.resolution = resolution, .margin = 1.0}, "synthetic");
}

TEST(DrivableRaster, SquareHasExactAreaAndGrid) {
  const DrivableRaster r = build(mapOf({rectangle(0, 0, 10, 10)}));
  EXPECT_DOUBLE_EQ(r.area(), 100.0);
  const GridGeometry& g = r.geometry();
  EXPECT_NEAR(g.origin.x(), -1.0, 1e-12);
  EXPECT_NEAR(g.origin.y(), -1.0, 1e-12);
  EXPECT_EQ(g.cols, 120);
  EXPECT_EQ(g.rows, 120);
  EXPECT_TRUE(r.contains({0.05, 0.05}));
  EXPECT_TRUE(r.contains({9.95, 9.95}));
  EXPECT_FALSE(r.contains({-0.05, 5.0}));
  EXPECT_FALSE(r.contains({10.05, 5.0}));
  EXPECT_FALSE(r.contains({500.0, 5.0}));
  EXPECT_FALSE(r.contains({NAN, 5.0}));
  // Row 0 is south: the cell holding (5, 0.05) is row 10 (origin y = -1).
  EXPECT_TRUE(r.drivable(60, 10));
  EXPECT_FALSE(r.drivable(60, 9));
}

TEST(DrivableRaster, UnalignedShapesHaveTheirAreaWithinHalfACellAlongTheBoundary) {
  struct Case {
    const char* name;
    VectorMap map;
    double area, perimeter;
  };
  const std::vector<Case> cases = {
      {"offset square", mapOf({rectangle(0.033, 0.071, 10.033, 10.071)}), 100.0, 40.0},
      {"L-shape", mapOf({ring({{0.02, 0.03}, {8.02, 0.03}, {8.02, 3.03}, {3.02, 3.03}, {3.02, 10.03}, {0.02, 10.03}})}),
       8 * 3 + 3 * 7, 36.0},
      {"two squares sharing an edge and a third overlapping both",
       mapOf({rectangle(0.04, 0.04, 10.04, 10.04), rectangle(10.04, 0.04, 20.04, 10.04),
              rectangle(5.04, 5.04, 15.04, 15.04)}),
       250.0, 70.0},
      {"rotated square", mapOf({ring({{0, 0}, {6, 8}, {-2, 14}, {-8, 6}})}), 100.0, 40.0},
  };
  for (const Case& c : cases) {
    const DrivableRaster r = build(c.map);
    // Each boundary cell is misclassified by at most half its area on average.
    EXPECT_NEAR(r.area(), c.area, 0.5 * 0.1 * c.perimeter) << c.name;
    EXPECT_EQ(r.surfacePoints().size(), r.drivableCellCount()) << c.name;
  }
}

TEST(DrivableRaster, SharedEdgesAreInteriorAndCarryNoBoundaryPoints) {
  const DrivableRaster r = build(mapOf({rectangle(0.04, 0.04, 10.04, 10.04), rectangle(10.04, 0.04, 20.04, 10.04)}));
  EXPECT_NEAR(r.area(), 200.0, 0.5 * 0.1 * 60.0);
  EXPECT_TRUE(r.contains({10.04, 5.0}));
  EXPECT_TRUE(r.contains({10.0, 5.0}));
  size_t onOuter = 0;
  for (const Eigen::Vector2d& p : r.boundaryPoints()) {
    const bool interiorOfSharedEdge = std::abs(p.x() - 10.04) < 1e-9 && p.y() > 0.3 && p.y() < 9.8;
    EXPECT_FALSE(interiorOfSharedEdge) << p.transpose();
    const double toOuter = std::min({std::abs(p.x() - 0.04), std::abs(p.x() - 20.04), std::abs(p.y() - 0.04),
                                     std::abs(p.y() - 10.04)});
    if (toOuter < 0.1 + 1e-9) ++onOuter;  // the shared edge's last sample sits one cell inside
  }
  EXPECT_EQ(onOuter, r.boundaryPoints().size());
  // The outer perimeter of 60 m traced every 0.1 m.
  EXPECT_NEAR(double(r.boundaryPoints().size()), 600.0, 4.0);
}

TEST(DrivableRaster, SurfacePointsAreTheDrivableCellCentres) {
  const DrivableRaster r = build(mapOf({ring({{0, 0}, {4, 0}, {0, 3}})}), 0.5);
  const std::vector<Eigen::Vector2d> points = r.surfacePoints();
  ASSERT_EQ(points.size(), r.drivableCellCount());
  for (const Eigen::Vector2d& p : points) {
    EXPECT_TRUE(r.contains(p));
    EXPECT_LT(p.x() / 4 + p.y() / 3, 1.0);  // inside the triangle
  }
  const std::vector<uint8_t> bytes = r.cellBytes();
  EXPECT_EQ(size_t(std::count(bytes.begin(), bytes.end(), 1)), points.size());
}

TEST(DrivableRaster, BadInputThrowsError) {
  const auto fails = [](const VectorMap& map, const DrivableRasterOptions& o, const std::string& mentions) {
    try {
      DrivableRaster::build(map, o, "some/map.json");
      ADD_FAILURE() << "expected an Error mentioning " << mentions;
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), "some/map.json");
      EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
    }
  };
  const DrivableRasterOptions ok;
  fails(VectorMap{}, ok, "no drivable areas");
  fails(mapOf({ring({{0, 0}, {1, 1}})}), ok, "needs at least 3");
  fails(mapOf({ring({{0, 0}, {1, 1}, {2, 2}})}), ok, "zero area");
  fails(mapOf({ring({{0, 0}, {1, NAN}, {2, 0}})}), ok, "non-finite");
  fails(mapOf({ring({{0, 0}, {1e7, 0}, {0, 1e7}})}), ok, "more than the limit");
  fails(mapOf({rectangle(0, 0, 1, 1)}), {.resolution = 0.0}, "resolution");
  fails(mapOf({rectangle(0, 0, 1, 1)}), {.resolution = NAN}, "resolution");
  fails(mapOf({rectangle(0, 0, 1, 1)}), {.resolution = 0.1, .margin = 0.01}, "margin");
  fails(mapOf({rectangle(0, 0, 0.01, 0.01)}), ok, "cover no cell");
}

class RealDrivableRaster : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    map_ = new VectorMap(readVectorMap(realVectorMap()));
    raster_ = new DrivableRaster(DrivableRaster::build(*map_, {}, "real"));
  }
  static void TearDownTestSuite() {
    delete raster_;
    delete map_;
  }
  static VectorMap* map_;
  static DrivableRaster* raster_;
};
VectorMap* RealDrivableRaster::map_ = nullptr;
DrivableRaster* RealDrivableRaster::raster_ = nullptr;

TEST_F(RealDrivableRaster, UnionAreaMatchesExactPolygonUnion) {
  BMultiPolygon united;
  for (const DrivableArea& a : map_->drivableAreas) {
    BMultiPolygon next;
    bg::union_(united, toBoost(a.areaBoundary), next);
    united = std::move(next);
  }
  double sumOfAreas = 0.0;
  for (const DrivableArea& a : map_->drivableAreas) sumOfAreas += bg::area(toBoost(a.areaBoundary));
  const double exact = bg::area(united);
  ASSERT_GT(exact, 1000.0);
  EXPECT_LT(exact, sumOfAreas);  // the polygons overlap: a plain sum would count twice
  EXPECT_NEAR(raster_->area() / exact, 1.0, 0.005) << "raster " << raster_->area() << " m^2, exact " << exact;
}

TEST_F(RealDrivableRaster, PointInRegionMatchesExactPointInPolygon) {
  std::vector<BPolygon> polygons;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e18), hi = -lo;
  for (const DrivableArea& a : map_->drivableAreas) {
    polygons.push_back(toBoost(a.areaBoundary));
    const Polyline3& r = a.areaBoundary;
    for (size_t i = 0; i < r.size(); ++i) {
      edges.emplace_back(r[i].head<2>(), r[(i + 1) % r.size()].head<2>());
      lo = lo.cwiseMin(r[i].head<2>());
      hi = hi.cwiseMax(r[i].head<2>());
    }
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ux(lo.x() - 5, hi.x() + 5), uy(lo.y() - 5, hi.y() + 5);
  const double cell = raster_->geometry().resolution;
  size_t tested = 0, agree = 0, inside = 0;
  while (tested < 100000) {
    const Eigen::Vector2d p(ux(rng), uy(rng));
    bool nearBoundary = false;
    for (const auto& [a, b] : edges) {
      if (segmentDistance(p, a, b) <= cell) {
        nearBoundary = true;
        break;
      }
    }
    if (nearBoundary) continue;
    const bool exact = std::any_of(polygons.begin(), polygons.end(),
                                   [&](const BPolygon& poly) { return bg::within(BPoint(p.x(), p.y()), poly); });
    ++tested;
    inside += exact;
    agree += exact == raster_->contains(p);
  }
  EXPECT_EQ(agree, tested);
  EXPECT_GT(inside, 5000u);  // the sample covers both sides
  EXPECT_GT(tested - inside, 5000u);
}

TEST_F(RealDrivableRaster, BoundaryPointsLieOnTheUnionBoundary) {
  const std::vector<Eigen::Vector2d>& points = raster_->boundaryPoints();
  ASSERT_GT(points.size(), 10000u);
  size_t mixed = 0;
  for (const Eigen::Vector2d& p : points) {
    // Within one cell of the point there are both drivable and non-drivable cells.
    bool in = false, out = false;
    for (double dx : {-0.1, 0.0, 0.1}) {
      for (double dy : {-0.1, 0.0, 0.1}) (raster_->contains(p + Eigen::Vector2d(dx, dy)) ? in : out) = true;
    }
    mixed += in && out;
  }
  EXPECT_GT(double(mixed), 0.99 * double(points.size()));
}

// A window of the map (a check along one drive): only that part is rastered, its cells and
// boundary points are the whole raster's there, and the distance field agrees wherever the nearest
// boundary within 10 m lies inside the window.
TEST_F(RealDrivableRaster, AWindowRastersOnlyThatPartAndAgreesWithTheWhole) {
  const GridGeometry& whole = raster_->geometry();
  const Eigen::Vector2d centre = whole.origin + 0.5 * whole.resolution * Eigen::Vector2d(whole.cols, whole.rows);
  DrivableRasterOptions options;
  options.window = Eigen::AlignedBox2d(centre.array() - 60.0, centre.array() + 60.0);
  const DrivableRaster part = DrivableRaster::build(*map_, options, "real");
  const GridGeometry& g = part.geometry();
  EXPECT_NEAR(g.cols * g.resolution, 120.0, 0.2);
  EXPECT_NEAR(g.rows * g.resolution, 120.0, 0.2);
  size_t drivable = 0;
  for (int r = 0; r < g.rows; r += 7)
    for (int c = 0; c < g.cols; c += 7) {
      const Eigen::Vector2d p = g.cellCentre(c, r);
      ASSERT_EQ(part.drivable(c, r), raster_->contains(p)) << p.transpose();
      drivable += part.drivable(c, r);
    }
  EXPECT_GT(drivable, 50u);
  size_t inside = 0;
  for (const Eigen::Vector2d& p : raster_->boundaryPoints()) inside += options.window->contains(p);
  EXPECT_NEAR(double(part.boundaryPoints().size()), double(inside), 0.01 * double(inside));
  const Eigen::AlignedBox2d grid(options.window->min().array() - 0.1, options.window->max().array() + 0.1);  // whole cells
  for (const Eigen::Vector2d& p : part.boundaryPoints()) ASSERT_TRUE(grid.contains(p)) << p.transpose();

  const BoundaryDistance wholeDistance = BoundaryDistance::build(*raster_), partDistance = BoundaryDistance::build(part);
  for (double x = -45.0; x <= 45.0; x += 3.7)
    for (double y = -45.0; y <= 45.0; y += 3.7) {
      const Eigen::Vector2d p = centre + Eigen::Vector2d(x, y);
      const double d = wholeDistance.distance(p);
      if (std::abs(d) <= 10.0) ASSERT_NEAR(partDistance.distance(p), d, 1e-4) << p.transpose();
    }
}

}  // namespace
}  // namespace hdprior

#pragma GCC diagnostic pop
