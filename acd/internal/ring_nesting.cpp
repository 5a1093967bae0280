#include "acd/internal/ring_nesting.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <Eigen/Geometry>
#include <vector>

#include "acd/internal/exact_predicates.h"

namespace acdplan::acd::internal {
namespace {

// Whether `inner` lies inside `outer`, judged exactly at its first vertex off `outer`'s
// boundary.
bool Contains(const Ring2d& outer, const Ring2d& inner) {
  if (outer.size() < 3) return false;
  std::vector<Kernel::Point_2> points;
  points.reserve(outer.size());
  for (const Point2d& p : outer) points.push_back(ToCgal(p));
  for (const Point2d& p : inner) {
    const CGAL::Bounded_side side =
        CGAL::bounded_side_2(points.begin(), points.end(), ToCgal(p), Kernel());
    if (side != CGAL::ON_BOUNDARY) return side == CGAL::ON_BOUNDED_SIDE;
  }
  return false;
}

Eigen::AlignedBox2d BoxOf(const Ring2d& ring) {
  Eigen::AlignedBox2d box;
  for (const Point2d& p : ring) box.extend(p);
  return box;
}

}  // namespace

std::vector<Polygon2d> PolygonsByNesting(const std::vector<Ring2d>& rings) {
  const size_t count = rings.size();
  if (count == 1) return {Polygon2d{rings[0], {}}};
  std::vector<Eigen::AlignedBox2d> boxes(count);
  for (size_t i = 0; i < count; ++i) boxes[i] = BoxOf(rings[i]);
  // containers[i]: the rings that contain ring i.
  std::vector<std::vector<size_t>> containers(count);
  for (size_t i = 0; i < count; ++i) {
    for (size_t j = 0; j < count; ++j) {
      if (i != j && boxes[j].contains(boxes[i]) && Contains(rings[j], rings[i])) {
        containers[i].push_back(j);
      }
    }
  }
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
