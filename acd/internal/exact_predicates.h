#pragma once
// Exact geometric predicates on double coordinates (CGAL's filtered Epick kernel). Internal:
// include only from .cpp files of the acd library, so CGAL stays out of the public headers.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

inline Kernel::Point_2 ToCgal(const Point2d& p) { return {p.x(), p.y()}; }

/// The sign of left - right, two rounded products of rounded differences as orient2d forms
/// them, when their rounding cannot flip it (Shewchuk's orient2d error bound
/// (3 + 16 eps) eps (|left| + |right|), which certifies the sign of the rounded difference);
/// 0 when it might.
inline int FilteredTurnSign(double left, double right) {
  const double det = left - right;
  constexpr double kErrorBound = 3.3306690738754716e-16;
  const double bound = kErrorBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}

/// CGAL's exact orientation, for the few cases the filter below leaves open. Kept out of line:
/// inlined, its code would keep the compiler from inlining the filtered predicates into the
/// hull and cut loops that call them per vertex.
[[gnu::noinline]] inline int ExactOrientation(const Point2d& a, const Point2d& b,
                                              const Point2d& c) {
  return static_cast<int>(CGAL::orientation(ToCgal(a), ToCgal(b), ToCgal(c)));
}

/// Sign of the turn a -> b -> c, exactly: +1 left (counter-clockwise), 0 collinear, -1 right.
/// A floating-point filter decides the clear cases (FilteredTurnSign()); CGAL's exact predicate
/// decides the rest.
inline int Orientation(const Point2d& a, const Point2d& b, const Point2d& c) {
  const int sign =
      FilteredTurnSign((a.x() - c.x()) * (b.y() - c.y()), (a.y() - c.y()) * (b.x() - c.x()));
  return sign != 0 ? sign : ExactOrientation(a, b, c);
}

/// Orientation(a, b, c) for loops that test many points c against one edge a -> b: `ab` must
/// be b - a as rounded, computed once per edge. The filter runs on the cyclic permutation
/// (b, c, a), which has the same sign, with a as the pivot, so it is as certain as
/// Orientation()'s, and both return the exact sign.
inline int OrientationAlong(const Point2d& a, const Point2d& ab, const Point2d& b,
                            const Point2d& c) {
  const int sign = FilteredTurnSign(ab.x() * (c.y() - a.y()), ab.y() * (c.x() - a.x()));
  return sign != 0 ? sign : ExactOrientation(a, b, c);
}

/// The orientation of a simple ring without repeated points, exactly: +1 counter-clockwise, -1
/// clockwise, 0 for fewer than 3 vertices or all of them on a line. The turn at the
/// lexicographically smallest vertex, a vertex of the hull, is the sign of the ring's area even
/// where the area underflows a double (a sliver of subnormal width).
inline int RingOrientation(const Ring2d& ring) {
  const size_t n = ring.size();
  if (n < 3) return 0;
  size_t lowest = 0;
  for (size_t i = 1; i < n; ++i) {
    const Point2d& p = ring[i];
    const Point2d& q = ring[lowest];
    if (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y())) lowest = i;
  }
  return Orientation(ring[(lowest + n - 1) % n], ring[lowest], ring[(lowest + 1) % n]);
}

/// Whether the ray from `p` toward +x crosses the edge a-b: the even-odd rule's test per edge,
/// with the half-open rule on y (a ray through a vertex counts once) and an exact side test.
inline bool RayCrossesEdge(const Point2d& p, const Point2d& a, const Point2d& b) {
  const bool a_above = a.y() > p.y(), b_above = b.y() > p.y();
  if (a_above == b_above || p.x() > std::max(a.x(), b.x())) return false;
  // The ray meets the edge iff p lies left of the upward-directed edge.
  const int side = Orientation(a, b, p);
  return b_above ? side > 0 : side < 0;
}

}  // namespace acdplan::acd::internal
