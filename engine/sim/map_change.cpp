#include "engine/sim/map_change.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include <nlohmann/json.hpp>

#include "engine/error.h"

namespace hdprior {

ChangedMap changeDrivableAreas(const VectorMap& world, double fraction, uint64_t seed) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) throw Error("option --map-change", "must be between 0 and 1");
  ChangedMap out{world, {}};
  const size_t n = world.drivableAreas.size();
  const size_t count = size_t(std::llround(fraction * double(n)));
  if (count == 0) return out;
  std::mt19937_64 rng(seed ^ 0x3a9c4a11ULL);
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::shuffle(order.begin(), order.end(), rng);
  order.resize(count);
  std::sort(order.begin(), order.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int64_t nextId = 0;
  for (const DrivableArea& a : world.drivableAreas) nextId = std::max(nextId, a.id + 1);

  std::vector<bool> removed(n, false);
  std::vector<DrivableArea> added;
  for (size_t i : order) {
    const DrivableArea& area = world.drivableAreas[i];
    const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
    if (kind == 0) {
      removed[i] = true;
      out.changes.push_back({DrivableAreaChange::Kind::Removed, area.id, Eigen::Vector2d::Zero()});
    } else if (kind == 1) {
      const double angle = 2 * std::numbers::pi * unit(rng), dist = 1.0 + 2.0 * unit(rng);
      const Eigen::Vector2d shift(dist * std::cos(angle), dist * std::sin(angle));
      for (Eigen::Vector3d& v : out.map.drivableAreas[i].areaBoundary) v.head<2>() += shift;
      out.changes.push_back({DrivableAreaChange::Kind::Shifted, area.id, shift});
    } else {
      Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
      for (const Eigen::Vector3d& v : area.areaBoundary) centroid += v.head<2>();
      centroid /= double(area.areaBoundary.size());
      const size_t k = std::uniform_int_distribution<size_t>(0, area.areaBoundary.size() - 1)(rng);
      const Eigen::Vector3d base = area.areaBoundary[k];
      Eigen::Vector2d u = base.head<2>() - centroid;
      u = u.norm() > 1e-6 ? Eigen::Vector2d(u.normalized()) : Eigen::Vector2d(1, 0);
      const Eigen::Vector2d w(-u.y(), u.x());
      DrivableArea strip;
      strip.id = nextId++;
      for (const Eigen::Vector2d& c : {Eigen::Vector2d(base.head<2>() - 4.0 * w), Eigen::Vector2d(base.head<2>() + 4.0 * w),
                                       Eigen::Vector2d(base.head<2>() + 4.0 * w + 15.0 * u),
                                       Eigen::Vector2d(base.head<2>() - 4.0 * w + 15.0 * u)})
        strip.areaBoundary.emplace_back(c.x(), c.y(), base.z());
      added.push_back(strip);
      out.changes.push_back({DrivableAreaChange::Kind::Added, strip.id, Eigen::Vector2d::Zero()});
    }
  }
  std::vector<DrivableArea> kept;
  for (size_t i = 0; i < n; ++i)
    if (!removed[i]) kept.push_back(out.map.drivableAreas[i]);
  kept.insert(kept.end(), added.begin(), added.end());
  std::sort(kept.begin(), kept.end(), [](const DrivableArea& a, const DrivableArea& b) { return a.id < b.id; });
  out.map.drivableAreas = std::move(kept);
  if (out.map.drivableAreas.empty()) throw Error("option --map-change", "would remove every drivable area");
  return out;
}

std::string mapChangesToJson(double fraction, const std::vector<DrivableAreaChange>& changes) {
  nlohmann::json j;
  j["fraction"] = fraction;
  j["changes"] = nlohmann::json::array();
  for (const DrivableAreaChange& c : changes) {
    const char* kind = c.kind == DrivableAreaChange::Kind::Removed   ? "removed"
                       : c.kind == DrivableAreaChange::Kind::Shifted ? "shifted"
                                                                     : "added";
    j["changes"].push_back({{"drivable_area_id", c.id}, {"change", kind}, {"shift_m", {c.shift.x(), c.shift.y()}}});
  }
  return j.dump(2) + "\n";
}

}  // namespace hdprior
