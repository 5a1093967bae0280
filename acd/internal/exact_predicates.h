#pragma once
// Exact geometric predicates on double coordinates (CGAL's filtered Epick kernel). Internal:
// include only from .cpp files of the acd library, so CGAL stays out of the public headers.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

inline Kernel::Point_2 ToCgal(const Point2d& p) { return {p.x(), p.y()}; }

/// Sign of the turn a -> b -> c, exactly: +1 left (counter-clockwise), 0 collinear, -1 right.
inline int Orientation(const Point2d& a, const Point2d& b, const Point2d& c) {
  return static_cast<int>(CGAL::orientation(ToCgal(a), ToCgal(b), ToCgal(c)));
}

}  // namespace acdplan::acd::internal
