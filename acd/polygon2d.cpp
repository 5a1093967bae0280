#include "acd/polygon2d.h"

#include <algorithm>
#include <cmath>

#include "acd/internal/centroid_area.h"

namespace acdplan::acd {

namespace {

// a + b = *sum + *error exactly (Knuth's TwoSum: no branch on which of a, b is larger, which
// comes at random along a ring).
void TwoSum(double a, double b, double* sum, double* error) {
  const double s = a + b;
  const double virtual_b = s - a;
  *error = (a - (s - virtual_b)) + (b - virtual_b);
  *sum = s;
}

// Exact twice the signed area of `ring` (Shewchuk, "Adaptive precision floating-point arithmetic
// and fast robust geometric predicates", 1997): every cross product x_i y_j - y_i x_j is split
// into four doubles by TwoProduct (std::fma gives the rounding error of a product exactly) and
// added to a nonoverlapping expansion by Grow-Expansion with zero elimination, so the sum is
// exact as long as no product overflows or its error term underflows (|coordinates| within
// about 1e-145 .. 1e153). An expansion of nonoverlapping doubles has at most ~40 components.
// Returns the expansion's value rounded from the smallest component up, whose sign is the sign
// of the largest component, i.e. of the exact sum.
double ExactTwiceSignedArea(const Ring2d& ring) {
  std::vector<double> expansion;  // Nonoverlapping, increasing magnitude.
  auto grow = [&expansion](double b) {
    double q = b;
    size_t out = 0;
    for (size_t i = 0; i < expansion.size(); ++i) {
      double error;
      TwoSum(q, expansion[i], &q, &error);
      if (error != 0.0) expansion[out++] = error;
    }
    expansion.resize(out);
    if (q != 0.0) expansion.push_back(q);
  };
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Point2d& a = ring[i];
    const Point2d& b = ring[i + 1 == n ? 0 : i + 1];
    const double p = a.x() * b.y();
    const double q = -(a.y() * b.x());
    grow(std::fma(a.x(), b.y(), -p));
    grow(std::fma(-a.y(), b.x(), -q));
    grow(p);
    grow(q);
  }
  if (expansion.empty()) return 0.0;
  double value = 0.0;
  for (const double e : expansion) value += e;
  const double largest = expansion.back();
  return (value > 0.0) == (largest > 0.0) && value != 0.0 ? value : largest;
}

// a * b = product + error exactly (Dekker's TwoProduct with Veltkamp's split, no FMA needed;
// exact while |a|, |b| < 2^996 and the error does not underflow).
void TwoProduct(double a, double b, double* product, double* error) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1.
  const double ca = kSplitter * a, cb = kSplitter * b;
  const double a_hi = ca - (ca - a), a_lo = a - a_hi;
  const double b_hi = cb - (cb - b), b_lo = b - b_hi;
  *product = a * b;
  *error = ((a_hi * b_hi - *product) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
}

// Twice the signed area as if summed in twice the working precision, without translating (Dot2
// of Ogita, Rump and Oishi, "Accurate sum and dot product", 2005): products split exactly,
// sums compensated. Sets `*error_bound` to its Theorem 5.3 bound, u |result| +
// gamma_{2n}^2 sum |products| (with slack).
double CompensatedTwiceSignedArea(const Ring2d& ring, double* error_bound) {
  const size_t n = ring.size();
  double sum = 0.0, compensation = 0.0, magnitude = 0.0;
  auto add = [&](double x) {
    double error;
    TwoSum(sum, x, &sum, &error);
    compensation += error;
  };
  for (size_t i = 0; i < n; ++i) {
    const Point2d& a = ring[i];
    const Point2d& b = ring[i + 1 == n ? 0 : i + 1];
    double p, e, q, f;
    TwoProduct(a.x(), b.y(), &p, &e);
    TwoProduct(-a.y(), b.x(), &q, &f);
    add(p);
    add(q);
    compensation += e + f;
    magnitude += std::abs(p) + std::abs(q);
  }
  const double result = sum + compensation;
  constexpr double u = 1.12e-16;
  const double gamma = 2.0 * static_cast<double>(n) * u * 1.01;
  *error_bound = 1.01 * u * std::abs(result) + 1.01 * gamma * gamma * magnitude;
  return result;
}

}  // namespace

double SignedArea(const Ring2d& ring) {
  const size_t n = ring.size();
  if (n < 3) return 0.0;
  // Relative to the first vertex: far from the origin the plain shoelace sum cancels.
  const Point2d origin = ring.front();
  double twice_area = 0.0, compensation = 0.0;  // A compensated sum (Neumaier's).
  double magnitude = 0.0;
  for (size_t i = 1; i + 1 < n; ++i) {
    const Point2d a = ring[i] - origin;
    const Point2d b = ring[i + 1] - origin;
    const double left = a.x() * b.y(), right = a.y() * b.x();
    const double term = left - right;
    double error;
    TwoSum(twice_area, term, &twice_area, &error);
    compensation += error;
    magnitude += std::abs(left) + std::abs(right);
  }
  twice_area += compensation;
  // Error bound of the sum above, u = 2^-53 ~ 1.11e-16 (with slack): each term errs by at most
  // 4u of its two products (the translation, the products, the subtraction), the compensated
  // summation by 2u of the result plus 2nu^2 of `magnitude`. Where it is not small against
  // the result, as when the terms cancel (a spike 1e21 long and 1 wide), the rounded sum may be
  // noise, even of the wrong sign: then the exact sum decides.
  constexpr double u = 1.12e-16;
  const double error =
      (4.1 + 2.0 * static_cast<double>(n) * u) * u * magnitude + 2.1 * u * std::abs(twice_area);
  if (error <= 0x1p-36 * std::abs(twice_area)) return 0.5 * twice_area;
  // Long winding pockets cancel that much; twice the precision settles nearly all of them.
  double compensated_error = 0.0;
  const double compensated = CompensatedTwiceSignedArea(ring, &compensated_error);
  if (compensated_error <= 0x1p-36 * std::abs(compensated)) return 0.5 * compensated;
  return 0.5 * ExactTwiceSignedArea(ring);
}

double Area(const Polygon2d& polygon) {
  double area = SignedArea(polygon.outer);
  for (const Ring2d& hole : polygon.holes) area -= std::abs(SignedArea(hole));
  return area;
}

namespace {
// First moment of the region bounded by `ring` (signed like SignedArea), divided by 6;
// `signed_area` is SignedArea(ring).
Point2d RingMoment(const Ring2d& ring, double signed_area) {
  const size_t n = ring.size();
  Point2d moment = Point2d::Zero();
  // Translate to the first vertex to keep the products small (cancellation at 1e6 scale).
  const Point2d origin = ring.empty() ? Point2d::Zero() : ring.front();
  for (size_t i = 0; i < n; ++i) {
    const Point2d a = ring[i] - origin;
    const Point2d b = ring[i + 1 == n ? 0 : i + 1] - origin;  // (No division per vertex.)
    const double cross = a.x() * b.y() - a.y() * b.x();
    moment += (a + b) * cross;
  }
  return moment / 6.0 + origin * signed_area;
}
}  // namespace

Point2d Centroid(const Polygon2d& polygon) {
  double area = 0.0;
  return internal::CentroidAndArea(polygon, &area);
}

namespace internal {

Point2d CentroidAndArea(const Polygon2d& polygon, double* area) {
  // Each ring's signed area once; the area sums them as Area() does.
  double outer_area = SignedArea(polygon.outer);
  Point2d moment = RingMoment(polygon.outer, outer_area);
  for (const Ring2d& hole : polygon.holes) {
    const double hole_area = SignedArea(hole);
    // Holes are clockwise, so their signed moment already subtracts; be orientation-agnostic.
    const double sign = hole_area < 0 ? 1.0 : -1.0;
    moment += sign * RingMoment(hole, hole_area);
    outer_area -= std::abs(hole_area);
  }
  *area = outer_area;
  if (outer_area == 0.0) {
    // An area no double holds (a sliver of subnormal width): the moment is no better, and the
    // mean of the outer vertices lies in the sliver's hull.
    Point2d mean = Point2d::Zero();
    for (const Point2d& p : polygon.outer) mean += p;
    return polygon.outer.empty() ? mean : Point2d(mean / static_cast<double>(polygon.outer.size()));
  }
  return moment / outer_area;
}

}  // namespace internal

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
  // One square root of the largest square: the root is monotone and correctly rounded, so this
  // is the largest of the roots, to the bit.
  double radius2 = 0.0;
  for (const Point2d& p : polygon.outer) radius2 = std::max(radius2, (p - mean).squaredNorm());
  return std::sqrt(radius2);
}

Ring2d Reversed(const Ring2d& ring) { return Ring2d(ring.rbegin(), ring.rend()); }

}  // namespace acdplan::acd
