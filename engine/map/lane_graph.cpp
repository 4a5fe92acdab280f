#include "engine/map/lane_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "engine/error.h"

namespace hdprior {

double polylineLength(const Polyline3& line) {
  double length = 0.0;
  for (size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
  return length;
}

Polyline3 resampleByArcLength(const Polyline3& line, size_t n) {
  n = std::max<size_t>(n, 2);
  if (line.empty()) return {};
  const double total = polylineLength(line);
  if (line.size() == 1 || total <= 0.0) return Polyline3(n, line.front());
  Polyline3 out;
  out.reserve(n);
  size_t seg = 0;
  double segStart = 0.0;  // arc length at line[seg]
  for (size_t k = 0; k < n; ++k) {
    const double target = total * double(k) / double(n - 1);
    double segLength = (line[seg + 1] - line[seg]).norm();
    while (seg + 2 < line.size() && segStart + segLength < target) {
      segStart += segLength;
      ++seg;
      segLength = (line[seg + 1] - line[seg]).norm();
    }
    const double f = segLength > 0.0 ? std::clamp((target - segStart) / segLength, 0.0, 1.0) : 0.0;
    out.push_back(line[seg] + f * (line[seg + 1] - line[seg]));
  }
  out.back() = line.back();
  return out;
}

Polyline3 laneCenterline(const Polyline3& left, const Polyline3& right, double spacing) {
  const double longest = std::max(polylineLength(left), polylineLength(right));
  const size_t n = std::max<size_t>(2, size_t(std::ceil(longest / spacing)) + 1);
  const Polyline3 l = resampleByArcLength(left, n), r = resampleByArcLength(right, n);
  Polyline3 centre(n);
  for (size_t i = 0; i < n; ++i) centre[i] = 0.5 * (l[i] + r[i]);
  return centre;
}

LaneGraph::LaneGraph(const VectorMap& map, const LaneGraphOptions& options, const std::string& source) {
  if (!(options.centerlineSpacing > 0.0) || !std::isfinite(options.centerlineSpacing)) {
    throw Error(source, "centerline spacing must be positive");
  }
  lanes_.reserve(map.laneSegments.size());
  for (const LaneSegment& s : map.laneSegments) {
    if (s.leftLaneBoundary.empty() || s.rightLaneBoundary.empty()) {
      throw Error(source, "lane segment " + std::to_string(s.id) + " has an empty boundary");
    }
    Lane lane;
    lane.id = s.id;
    lane.isIntersection = s.isIntersection;
    lane.laneType = s.laneType;
    lane.centerline = laneCenterline(s.leftLaneBoundary, s.rightLaneBoundary, options.centerlineSpacing);
    lane.length = polylineLength(lane.centerline);
    index_.emplace(s.id, lanes_.size());
    lanes_.push_back(std::move(lane));
  }
  const auto link = [&](const std::vector<int64_t>& ids, std::vector<size_t>& out) {
    for (int64_t id : ids) {
      if (const auto i = indexOf(id)) out.push_back(*i); else ++droppedLinks_;
    }
  };
  for (size_t i = 0; i < lanes_.size(); ++i) {
    const LaneSegment& s = map.laneSegments[i];
    link(s.successors, lanes_[i].successors);
    link(s.predecessors, lanes_[i].predecessors);
    if (s.leftNeighborId) lanes_[i].leftNeighbor = indexOf(*s.leftNeighborId);
    if (s.rightNeighborId) lanes_[i].rightNeighbor = indexOf(*s.rightNeighborId);
  }
}

std::optional<size_t> LaneGraph::indexOf(int64_t id) const {
  const auto it = index_.find(id);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

std::vector<size_t> LaneGraph::reachable(size_t from) const {
  std::vector<bool> seen(lanes_.size(), false);
  std::vector<size_t> stack{from}, out;
  seen.at(from) = true;
  while (!stack.empty()) {
    const size_t i = stack.back();
    stack.pop_back();
    out.push_back(i);
    for (size_t j : lanes_[i].successors) {
      if (!seen[j]) {
        seen[j] = true;
        stack.push_back(j);
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<std::vector<size_t>> LaneGraph::shortestRoute(size_t from, size_t to) const {
  const size_t n = lanes_.size();
  if (from >= n || to >= n) return std::nullopt;
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<size_t> previous(n, n);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  dist[from] = 0.0;
  queue.emplace(0.0, from);
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > dist[i]) continue;
    if (i == to) break;
    for (size_t j : lanes_[i].successors) {
      const double nd = d + lanes_[i].length;
      if (nd < dist[j]) {
        dist[j] = nd;
        previous[j] = i;
        queue.emplace(nd, j);
      }
    }
  }
  if (std::isinf(dist[to])) return std::nullopt;
  std::vector<size_t> route{to};
  while (route.back() != from) route.push_back(previous[route.back()]);
  std::reverse(route.begin(), route.end());
  return route;
}

std::vector<size_t> LaneGraph::randomRoute(size_t start, double minLength, std::mt19937_64& rng) const {
  std::vector<size_t> route{start};
  double length = lanes_.at(start).length;
  // The step cap only matters for cycles of zero-length lanes.
  for (size_t steps = 0; length < minLength && steps < 100000; ++steps) {
    const std::vector<size_t>& next = lanes_[route.back()].successors;
    if (next.empty()) break;
    route.push_back(next[size_t(rng() % next.size())]);
    length += lanes_[route.back()].length;
  }
  return route;
}

Polyline3 LaneGraph::routeCenterline(std::span<const size_t> route) const {
  Polyline3 line;
  for (size_t i : route) {
    const Polyline3& c = lanes_.at(i).centerline;
    const bool joined = !line.empty() && (line.back() - c.front()).norm() < 1e-6;
    line.insert(line.end(), c.begin() + (joined ? 1 : 0), c.end());
  }
  return line;
}

namespace {
double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}
}  // namespace

std::optional<size_t> LaneGraph::nearestLane(const Eigen::Vector2d& city, double maxDistance) const {
  std::optional<size_t> best;
  double bestDistance = maxDistance;
  for (size_t i = 0; i < lanes_.size(); ++i) {
    const Polyline3& c = lanes_[i].centerline;
    for (size_t k = 0; k + 1 < c.size(); ++k) {
      const double d = segmentDistance(city, c[k].head<2>(), c[k + 1].head<2>());
      if (d <= bestDistance) {
        bestDistance = d;
        best = i;
      }
    }
  }
  return best;
}

}  // namespace hdprior
