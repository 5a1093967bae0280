#include "acd/internal/ring_nesting.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <vector>

#include "acd/internal/box_sweep.h"
#include "acd/internal/exact_predicates.h"

namespace acdplan::acd::internal {
namespace {

// A ring's vertices as CGAL points, for the exact point-in-ring tests.
std::vector<Kernel::Point_2> CgalPoints(const Ring2d& ring) {
  std::vector<Kernel::Point_2> points;
  points.reserve(ring.size());
  for (const Point2d& p : ring) points.push_back(ToCgal(p));
  return points;
}

// Whether `inner` lies inside the ring of `outer_points`, judged exactly at its first vertex off
// that ring's boundary.
bool Contains(const std::vector<Kernel::Point_2>& outer_points, const Ring2d& inner) {
  if (outer_points.size() < 3) return false;
  for (const Point2d& p : inner) {
    const CGAL::Bounded_side side =
        CGAL::bounded_side_2(outer_points.begin(), outer_points.end(), ToCgal(p), Kernel());
    if (side != CGAL::ON_BOUNDARY) return side == CGAL::ON_BOUNDED_SIDE;
  }
  return false;
}

}  // namespace

std::vector<Polygon2d> PolygonsByNesting(const std::vector<Ring2d>& rings) {
  const size_t count = rings.size();
  if (count == 1) return {Polygon2d{rings[0], {}}};
  std::vector<IdBox> boxes(count);
  for (size_t i = 0; i < count; ++i) boxes[i] = RingBox(rings[i], static_cast<int>(i));
  // containers[i]: the rings that contain ring i, in increasing order. Only rings whose boxes
  // overlap are tested (a sweep, not all pairs: a record may hold thousands of islands), and a
  // ring's CGAL points are made once, when it is first a candidate container.
  std::vector<std::vector<size_t>> containers(count);
  std::vector<std::vector<Kernel::Point_2>> points(count);
  auto test = [&](size_t outer, size_t inner) {
    if (!BoxWithin(boxes[inner], boxes[outer])) return;
    if (points[outer].empty()) points[outer] = CgalPoints(rings[outer]);
    if (Contains(points[outer], rings[inner])) containers[inner].push_back(outer);
  };
  ForEachSelfOverlap(boxes, [&](int a, int b) {
    test(static_cast<size_t>(a), static_cast<size_t>(b));
    test(static_cast<size_t>(b), static_cast<size_t>(a));
  });
  for (std::vector<size_t>& list : containers) std::sort(list.begin(), list.end());
  std::vector<int> polygon_of(count, -1);
  std::vector<Polygon2d> polygons;
  for (size_t i = 0; i < count; ++i) {
    if (containers[i].size() % 2 == 0) {
      polygon_of[i] = static_cast<int>(polygons.size());
      polygons.push_back({rings[i], {}});
    }
  }
  for (size_t i = 0; i < count; ++i) {
    if (containers[i].size() % 2 == 0) continue;
    // Its containers nest, so the innermost has one container fewer and is an outer ring;
    // rings that cross break that (PreparePolygons() rejects them later): then the innermost
    // outer ring among its containers, or none, and the ring stands as a polygon of its own.
    int owner = -1;
    for (const size_t j : containers[i]) {
      if (polygon_of[j] >= 0 &&
          (owner < 0 || containers[j].size() > containers[static_cast<size_t>(owner)].size())) {
        owner = static_cast<int>(j);
      }
    }
    if (owner >= 0) {
      polygons[static_cast<size_t>(polygon_of[static_cast<size_t>(owner)])].holes.push_back(
          rings[i]);
    } else {
      polygons.push_back({rings[i], {}});
    }
  }
  return polygons;
}

}  // namespace acdplan::acd::internal
