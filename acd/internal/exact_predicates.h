#pragma once
// Exact geometric predicates on double coordinates (CGAL's filtered Epick kernel). Internal:
// include only from .cpp files of the acd library, so CGAL stays out of the public headers.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

inline Kernel::Point_2 ToCgal(const Point2d& p) { return {p.x(), p.y()}; }

/// Sign of the turn a -> b -> c, exactly: +1 left (counter-clockwise), 0 collinear, -1 right.
/// A floating-point filter decides the clear cases (Shewchuk's orient2d error bound
/// (3 + 16 eps) eps |detsum|, which certifies the sign of the rounded determinant); CGAL's
/// exact predicate decides the rest.
inline int Orientation(const Point2d& a, const Point2d& b, const Point2d& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  constexpr double kErrorBound = 3.3306690738754716e-16;
  const double bound = kErrorBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return static_cast<int>(CGAL::orientation(ToCgal(a), ToCgal(b), ToCgal(c)));
}

}  // namespace acdplan::acd::internal
