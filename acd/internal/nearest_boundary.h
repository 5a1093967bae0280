#pragma once
// The boundary points of a polygon nearest to a point, offered nearest first from a spatial
// index instead of a sort of all of them. Internal.

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/internal/edge_grid.h"
#include "acd/internal/ring_blocks.h"
#include "acd/internal/thread_scratch.h"
#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// A point of a polygon's boundary: vertex `index` of ring `ring` (-1: the outer ring; k >= 0:
/// hole k), or, when `on_edge`, a new point on the edge from that vertex to the next.
struct BoundaryPoint {
  int ring = -1;
  int index = 0;
  bool on_edge = false;
  Point2d point = Point2d::Zero();
};

/// Feet of perpendiculars closer than this, relative to the edge length, to an edge end are
/// dropped: the end itself is a candidate too.
inline constexpr double kMinEdgeFraction = 1e-6;

/// The foot of the perpendicular from `p` on the edge u-w, if it lies inside the edge by more
/// than kMinEdgeFraction of its length.
inline std::optional<Point2d> EdgeFoot(const Point2d& p, const Point2d& u, const Point2d& w) {
  const Point2d e = w - u;
  const double s = (p - u).dot(e) / std::max(e.squaredNorm(), 1e-300);
  if (s > kMinEdgeFraction && s < 1.0 - kMinEdgeFraction) return Point2d(u + s * e);
  return std::nullopt;
}

/// Offers `accept(point)` the boundary points of `polygon` near `p` until it returns true, and
/// returns the point it took (nothing if it took none). The points: every vertex of the outer
/// ring and of each hole k with !skip_hole(k), and the EdgeFoot() of p on every outer edge. The
/// order: that of a sort of all of them by (squared distance to p, ring, index, on_edge), a
/// strict total order, so every standard library agrees on it, whichever search finds them.
/// `search(visit)` finds the edges in batches, the nearest about first: each call calls
/// `visit(EdgeGrid::Edge)` on the edges of the next batch (an edge may come again in a later
/// one) and returns a lower bound on the distance from p to the box of every edge not found yet,
/// +infinity once all are found. A point is offered once no edge left can hold one that sorts
/// before it: a search that ends near p costs the batches around p instead of a pass over the
/// whole polygon. `magnitude`: the largest magnitude of a vertex coordinate.
template <typename Search, typename SkipHole, typename Accept>
std::optional<BoundaryPoint> NearestAccepted(const Polygon2d& polygon, double magnitude,
                                             const Point2d& p, Search search, SkipHole skip_hole,
                                             Accept accept) {
  struct Near {
    double d2;
    BoundaryPoint end;
  };
  auto key = [](const Near& a) { return std::tie(a.d2, a.end.ring, a.end.index, a.end.on_edge); };
  auto later = [&](const Near& a, const Near& b) { return key(a) > key(b); };
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // A foot is a few roundings off its edge's box; this allows for a thousand times that.
  const double foot_noise = 1e-12 * std::max(magnitude, p.cwiseAbs().maxCoeff());
  double offered = -kInfinity;  // Every point with d2 <= offered has been offered.
  // A heap, nearest on top: points found and not offered yet. (The thread's buffer from the
  // last call: hole paths search once per link.)
  thread_local std::vector<Near> found;
  const ScratchScope found_scope(found);
  found.clear();
  auto push = [&](const Near& near) {
    found.push_back(near);
    std::push_heap(found.begin(), found.end(), later);
  };
  auto visit = [&](const EdgeGrid::Edge& edge) {
    // Vertex `index` lies in the box of the edge leaving it, so it is found with that edge.
    if (edge.ring >= 0 && skip_hole(edge.ring)) return;
    const Ring2d& ring = edge.ring < 0 ? polygon.outer : polygon.holes[edge.ring];
    const Point2d& u = ring[edge.index];
    const double d2 = (u - p).squaredNorm();
    if (d2 > offered) push({d2, {edge.ring, edge.index, false, u}});
    if (edge.ring >= 0) return;
    const int next = edge.index + 1 == static_cast<int>(ring.size()) ? 0 : edge.index + 1;
    if (const std::optional<Point2d> foot = EdgeFoot(p, u, ring[next])) {
      const double foot_d2 = (*foot - p).squaredNorm();
      if (foot_d2 > offered) push({foot_d2, {-1, edge.index, true, *foot}});
    }
  };
  std::optional<Near> last;  // The point offered last.
  while (offered < kInfinity) {
    const double reach = search(visit) - foot_noise;
    // Points not found yet lie farther than `reach`; their rounded d2 by a few ulps less.
    const double final_d2 = reach == kInfinity ? kInfinity
                            : reach > 0.0      ? reach * reach * (1.0 - 1e-12)
                                               : -1.0;
    while (!found.empty() && found.front().d2 <= final_d2) {
      std::pop_heap(found.begin(), found.end(), later);
      const Near near = found.back();
      found.pop_back();
      // An edge found in several batches is found as often; its copies pop one after another.
      if (last && key(near) == key(*last)) continue;
      if (accept(near.end)) return near.end;
      last = near;
    }
    offered = std::max(offered, final_d2);
  }
  return std::nullopt;
}

/// NearestAccepted() with the edges from `grid` (built on `polygon`), ring by ring of cells
/// around p (EdgeGrid::VisitRing()): O(cells + n log n) at worst.
template <typename SkipHole, typename Accept>
std::optional<BoundaryPoint> NearestAccepted(const Polygon2d& polygon, const EdgeGrid& grid,
                                             const Point2d& p, SkipHole skip_hole, Accept accept) {
  int cells = 0;
  auto search = [&](auto visit) { return grid.VisitRing(p, cells++, visit); };
  return NearestAccepted(polygon, grid.Magnitude(), p, search, skip_hole, accept);
}

/// NearestAccepted() with the edges from the blocks of the rings (`outer`: of polygon.outer,
/// `holes`: of polygon.holes), one block at a time by the distance of its box, holes skipped
/// whole: no index to build, for a few searches on a piece. `magnitude`: as for the first form.
template <typename SkipHole, typename Accept>
std::optional<BoundaryPoint> NearestAccepted(const Polygon2d& polygon, const RingBlocks& outer,
                                             const HoleBlocks& holes, double magnitude,
                                             const Point2d& p, SkipHole skip_hole, Accept accept) {
  // The blocks not searched yet: (squared distance, id), id < outer.Count() for the outer
  // ring's. Most searches end within a few blocks, so the nearest is found by a scan for the
  // first few, and the rest become a heap (nearest on top) only after that.
  thread_local std::vector<std::pair<double, int>> queue;  // (As `found` above.)
  const ScratchScope queue_scope(queue);
  queue.clear();
  for (int b = 0; b < outer.Count(); ++b) {
    queue.emplace_back(BoxSquaredDistance(outer[b].min, outer[b].max, p), b);
  }
  for (int b = 0; b < holes.Count(); ++b) {
    if (skip_hole(holes[b].hole)) continue;
    queue.emplace_back(BoxSquaredDistance(holes[b].min, holes[b].max, p), outer.Count() + b);
  }
  auto nearest_scanned = [&] {
    size_t best = 0;
    for (size_t k = 1; k < queue.size(); ++k) {
      if (queue[k].first < queue[best].first) best = k;
    }
    return best;
  };
  constexpr int kScannedRounds = 8;
  const auto nearer = std::greater<std::pair<double, int>>();
  int round = 0;
  size_t next = nearest_scanned();  // Before the heap: where the nearest block is.
  auto search = [&](auto visit) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    if (queue.empty()) return kInfinity;
    if (round < kScannedRounds) {
      std::swap(queue[next], queue.back());
    } else {
      std::pop_heap(queue.begin(), queue.end(), nearer);
    }
    const int id = queue.back().second;
    queue.pop_back();
    if (id < outer.Count()) {
      for (int i = outer.Begin(id); i < outer.End(id); ++i) visit(EdgeGrid::Edge{-1, i});
    } else {
      const HoleBlocks::Block& block = holes[id - outer.Count()];
      for (int i = block.begin; i < block.end; ++i) visit(EdgeGrid::Edge{block.hole, i});
    }
    if (queue.empty()) return kInfinity;
    ++round;
    if (round < kScannedRounds) {
      next = nearest_scanned();
      // The boxes bound their vertices' squared distances from below (BoxSquaredDistance()).
      return std::sqrt(queue[next].first);
    }
    if (round == kScannedRounds) std::make_heap(queue.begin(), queue.end(), nearer);
    return std::sqrt(queue.front().first);
  };
  return NearestAccepted(polygon, magnitude, p, search, skip_hole, accept);
}

}  // namespace acdplan::acd::internal
