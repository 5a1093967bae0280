#pragma once
// Rounding exact (Epeck) numbers to doubles reproducibly. Internal: include only from .cpp files
// (of acd, or of a library above it such as envs), so CGAL stays out of the public headers.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <utility>

namespace acdplan::acd::internal {

/// An exact rational rounded to a double: the one rule by which exact values become output.
/// Toward zero (GMP's mpq_get_d() rule), decided by exact comparisons: CGAL::to_double() would
/// make the result depend on the rational type CGAL was built with (mpq_class truncates;
/// boost::multiprecision's gmp_rational, its type without gmpxx, as in a libc++ build, rounds
/// to nearest), and with it every constructed point of a repair and of a 3D decomposition.
inline double RoundToDouble(const CGAL::Epeck::Exact_kernel::FT& x) {
  using Rational = CGAL::Epeck::Exact_kernel::FT;
  const std::pair<double, double> bounds = CGAL::to_interval(x);  // Within a few ulps.
  if (bounds.first == bounds.second) return bounds.first;         // x is a double.
  // From the bound on zero's side, step toward x while the next double does not pass it.
  const bool negative = CGAL::is_negative(x);
  double rounded = negative ? bounds.second : bounds.first;
  const double away =
      negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  for (double next = std::nextafter(rounded, away);
       std::isfinite(next) && (negative ? Rational(next) >= x : Rational(next) <= x);
       next = std::nextafter(rounded, away)) {
    rounded = next;
  }
  return rounded;
}

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
