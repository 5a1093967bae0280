#pragma once
// Rounding exact (Epeck) numbers to doubles reproducibly. Internal: include only from .cpp files
// (of acd, or of a library above it such as envs), so CGAL stays out of the public headers.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <Eigen/Core>
#include <utility>

namespace acdplan::acd::internal {

/// An exact rational rounded to a double: the one rule by which exact values become output.
inline double RoundToDouble(const CGAL::Epeck::Exact_kernel::FT& x) { return CGAL::to_double(x); }

/// A lazy-exact number rounded as its exact value is (above): to a double that depends on the
/// value of `x` alone.
///
/// Why not CGAL::to_double(): on a lazy-exact number it returns the midpoint of the current
/// interval approximation whenever that is narrower than 1e-5 relative. That interval is
/// tightened as a side effect of any exact evaluation of the number or of a node it shares
/// with others (a predicate that the filter could not decide, an earlier to_double), so the
/// same construction rounds to different doubles from run to run, and the repaired mesh and the
/// decomposition built on it changed with it. Here an interval that is a single double is that
/// double (the value is exactly representable); otherwise the exact value is rounded.
inline double RoundToDouble(const CGAL::Epeck::FT& x) {
  const std::pair<double, double> bounds = CGAL::to_interval(x);
  if (bounds.first == bounds.second) return bounds.first;
  return RoundToDouble(CGAL::exact(x));
}

/// RoundToDouble() of each coordinate.
inline Eigen::Vector3d RoundToDouble(const CGAL::Epeck::Point_3& p) {
  return {RoundToDouble(p.x()), RoundToDouble(p.y()), RoundToDouble(p.z())};
}

/// RoundToDouble() of each coordinate.
inline Eigen::Vector2d RoundToDouble(const CGAL::Epeck::Point_2& p) {
  return {RoundToDouble(p.x()), RoundToDouble(p.y())};
}

}  // namespace acdplan::acd::internal
