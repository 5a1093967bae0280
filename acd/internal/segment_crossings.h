#pragma once
// The signed count of triangles a segment crosses, with exact predicates: ray parity and
// winding numbers of closed triangle shells. Internal: include only from .cpp files of the acd
// library (it brings in CGAL).

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace acdplan::acd::internal {

/// The signed count of the triangles `triangles[i]`, i in `candidates`, that the segment from
/// `from` to `to` crosses, +1 where it leaves through a triangle's front (the side its corners
/// turn counter-clockwise about); empty if it meets an edge or a vertex of one. Triangles
/// coplanar with `from`, or with `to`, do not count. Exact in any CGAL kernel with exact
/// predicates (Epick on double points, Epeck).
template <typename Triangle, typename Point>
std::optional<int> SegmentCrossings(const std::vector<Triangle>& triangles,
                                    const std::vector<size_t>& candidates, const Point& from,
                                    const Point& to) {
  int winding = 0;
  for (const size_t i : candidates) {
    const Triangle& t = triangles[i];
    const CGAL::Orientation side = CGAL::orientation(t[0], t[1], t[2], from);
    if (side == CGAL::COPLANAR) continue;
    const CGAL::Orientation end = CGAL::orientation(t[0], t[1], t[2], to);
    if (end == side || end == CGAL::COPLANAR) continue;
    const CGAL::Orientation o[3] = {CGAL::orientation(from, to, t[0], t[1]),
                                    CGAL::orientation(from, to, t[1], t[2]),
                                    CGAL::orientation(from, to, t[2], t[0])};
    const bool positive =
        o[0] == CGAL::POSITIVE || o[1] == CGAL::POSITIVE || o[2] == CGAL::POSITIVE;
    const bool negative =
        o[0] == CGAL::NEGATIVE || o[1] == CGAL::NEGATIVE || o[2] == CGAL::NEGATIVE;
    if (positive && negative) continue;  // The segment passes beside t.
    if (o[0] == CGAL::COPLANAR || o[1] == CGAL::COPLANAR || o[2] == CGAL::COPLANAR) {
      return std::nullopt;  // Through an edge or a vertex of t.
    }
    winding += side == CGAL::NEGATIVE ? 1 : -1;
  }
  return winding;
}

}  // namespace acdplan::acd::internal
