#include "acd/polygon2d.h"

#include <algorithm>

namespace acdplan::acd {

double SignedArea(const Ring2d& ring) {
  const size_t n = ring.size();
  if (n < 3) return 0.0;
  // Relative to the first vertex: far from the origin the plain shoelace sum cancels.
  const Point2d origin = ring.front();
  double twice_area = 0.0;
  for (size_t i = 1; i + 1 < n; ++i) {
    const Point2d a = ring[i] - origin;
    const Point2d b = ring[i + 1] - origin;
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice_area;
}

double Area(const Polygon2d& polygon) {
  double area = SignedArea(polygon.outer);
  for (const Ring2d& hole : polygon.holes) area -= std::abs(SignedArea(hole));
  return area;
}

namespace {
// First moment of the region bounded by `ring` (signed like SignedArea), divided by 6.
Point2d RingMoment(const Ring2d& ring) {
  const size_t n = ring.size();
  Point2d moment = Point2d::Zero();
  // Translate to the first vertex to keep the products small (cancellation at 1e6 scale).
  const Point2d origin = ring.empty() ? Point2d::Zero() : ring.front();
  for (size_t i = 0; i < n; ++i) {
    const Point2d a = ring[i] - origin;
    const Point2d b = ring[(i + 1) % n] - origin;
    const double cross = a.x() * b.y() - a.y() * b.x();
    moment += (a + b) * cross;
  }
  return moment / 6.0 + origin * SignedArea(ring);
}
}  // namespace

Point2d Centroid(const Polygon2d& polygon) {
  Point2d moment = RingMoment(polygon.outer);
  for (const Ring2d& hole : polygon.holes) {
    // Holes are clockwise, so their signed moment already subtracts; be orientation-agnostic.
    const double sign = SignedArea(hole) < 0 ? 1.0 : -1.0;
    moment += sign * RingMoment(hole);
  }
  return moment / Area(polygon);
}

int VertexCount(const Polygon2d& polygon) {
  size_t count = polygon.outer.size();
  for (const Ring2d& hole : polygon.holes) count += hole.size();
  return static_cast<int>(count);
}

double ReferenceRadius(const Polygon2d& polygon) {
  if (polygon.outer.empty()) return 0.0;
  Point2d mean = Point2d::Zero();
  for (const Point2d& p : polygon.outer) mean += p;
  mean /= static_cast<double>(polygon.outer.size());
  double radius = 0.0;
  for (const Point2d& p : polygon.outer) radius = std::max(radius, (p - mean).norm());
  return radius;
}

Ring2d Reversed(const Ring2d& ring) { return Ring2d(ring.rbegin(), ring.rend()); }

}  // namespace acdplan::acd
