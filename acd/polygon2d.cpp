#include "acd/polygon2d.h"

#include <algorithm>
#include <cmath>

namespace acdplan::acd {

namespace {

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
      const double sum = q + expansion[i];  // TwoSum(q, e_i) = sum + error, exactly.
      const double virtual_b = sum - q;
      const double error = (q - (sum - virtual_b)) + (expansion[i] - virtual_b);
      q = sum;
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

}  // namespace

double SignedArea(const Ring2d& ring) {
  const size_t n = ring.size();
  if (n < 3) return 0.0;
  // Relative to the first vertex: far from the origin the plain shoelace sum cancels.
  const Point2d origin = ring.front();
  double twice_area = 0.0;
  double magnitude = 0.0;
  for (size_t i = 1; i + 1 < n; ++i) {
    const Point2d a = ring[i] - origin;
    const Point2d b = ring[i + 1] - origin;
    const double left = a.x() * b.y(), right = a.y() * b.x();
    twice_area += left - right;
    magnitude += std::abs(left) + std::abs(right);
  }
  // A priori error of the sum above (the translation, both products and the subtraction err by
  // a few units in the last place of each term, the summation by n - 3 of `magnitude`; u =
  // 2^-53 ~ 1.11e-16, with slack). Where it is not small against the result, as when the
  // terms cancel (a spike 1e21 long and 1 wide), the rounded sum may be pure noise, even of the
  // wrong sign: then the exact sum decides.
  const double error = static_cast<double>(n + 8) * 1.2e-16 * magnitude;
  if (error <= 0x1p-42 * std::abs(twice_area)) return 0.5 * twice_area;
  return 0.5 * ExactTwiceSignedArea(ring);
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
