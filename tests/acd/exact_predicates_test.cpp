// acd/internal/exact_predicates.h: both orientation forms must return CGAL's exact sign, also
// where rounding decides it (points on or next to a line, far from the origin). And
// acd/internal/exact_rounding.h: exact values become doubles by one rule, toward zero.
#include "acd/internal/exact_predicates.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "acd/internal/exact_rounding.h"

namespace acdplan::acd::internal {
namespace {

int ExactSign(const Point2d& a, const Point2d& b, const Point2d& c) {
  return static_cast<int>(CGAL::orientation(ToCgal(a), ToCgal(b), ToCgal(c)));
}

// A uniform double in [lo, hi) from the engine's bits (the same on every standard library).
double Uniform(std::mt19937_64& engine, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(engine() >> 11) * 0x1.0p-53);
}

// Triples whose turn rounding can get wrong: c on the segment a-b as rounded, nudged by a few
// ulps, with the coordinates far from the origin; and plain random ones.
std::vector<std::array<Point2d, 3>> HardTriples() {
  std::mt19937_64 engine(20261202);
  std::vector<std::array<Point2d, 3>> triples;
  for (int k = 0; k < 4000; ++k) {
    const double offset = k % 2 == 0 ? 0.0 : 1e6;
    const Point2d a(offset + Uniform(engine, -1, 1), offset + Uniform(engine, -1, 1));
    const Point2d b(offset + Uniform(engine, -1, 1), offset + Uniform(engine, -1, 1));
    const double t = Uniform(engine, -0.5, 1.5);
    Point2d c = a + t * (b - a);
    const int nudge = static_cast<int>(engine() % 5) - 2;  // -2 .. 2 ulps in y.
    for (int step = 0; step < std::abs(nudge); ++step) {
      c.y() = std::nextafter(c.y(), nudge > 0 ? INFINITY : -INFINITY);
    }
    triples.push_back({a, b, c});
    triples.push_back({a, b, Point2d(Uniform(engine, -2, 2), Uniform(engine, -2, 2))});
  }
  // Exactly collinear: c = a + t (b - a) with dyadic coordinates and t, computed exactly.
  for (int k = 0; k < 200; ++k) {
    auto dyadic = [&] { return static_cast<double>(engine() % 4096) / 64.0 + 1e6; };
    const Point2d a(dyadic(), dyadic()), b(dyadic(), dyadic());
    const double t = static_cast<double>(engine() % 16) / 4.0 - 1.0;
    triples.push_back({a, b, a + t * (b - a)});
  }
  return triples;
}

TEST(ExactPredicatesTest, OrientationIsExactNearLines) {
  int collinear = 0, left = 0, right = 0;
  for (const auto& [a, b, c] : HardTriples()) {
    const int exact = ExactSign(a, b, c);
    EXPECT_EQ(Orientation(a, b, c), exact)
        << a.transpose() << " | " << b.transpose() << " | " << c.transpose();
    collinear += exact == 0;
    left += exact > 0;
    right += exact < 0;
  }
  // The set does exercise every sign, including exact zeros off the filter's clear cases.
  EXPECT_GT(collinear, 150);
  EXPECT_GT(left, 100);
  EXPECT_GT(right, 100);
}

TEST(ExactPredicatesTest, OrientationAlongAnEdgeIsExactNearLines) {
  int decided_near_line = 0;
  for (const auto& [a, b, c] : HardTriples()) {
    const Point2d ab = b - a;
    const int exact = ExactSign(a, b, c);
    EXPECT_EQ(OrientationAlong(a, ab, b, c), exact)
        << a.transpose() << " | " << b.transpose() << " | " << c.transpose();
    // Cyclic and reversed forms: the same edge seen from its other end flips the sign.
    EXPECT_EQ(OrientationAlong(b, a - b, a, c), -exact);
    if (std::abs((c - a).x() * ab.y() - (c - a).y() * ab.x()) < 1e-9) ++decided_near_line;
  }
  EXPECT_GT(decided_near_line, 1000);
}

// Toward zero whatever rational type CGAL uses (to_double() of boost's gmp_rational, its type
// without gmpxx, rounds 1/10 up to 0.1; mpq_class's truncates).
TEST(ExactRoundingTest, RoundsExactRationalsTowardZero) {
  using Rational = CGAL::Epeck::Exact_kernel::FT;
  const double below_tenth = std::nextafter(0.1, 0.0);  // 0.1 is the double above 1/10.
  EXPECT_EQ(RoundToDouble(Rational(1) / 10), below_tenth);
  EXPECT_EQ(RoundToDouble(Rational(-1) / 10), -below_tenth);
  EXPECT_EQ(RoundToDouble(Rational(1) / 5), std::nextafter(0.2, 0.0));  // 0.2 is above 1/5,
  EXPECT_EQ(RoundToDouble(Rational(1) / 3), 1.0 / 3.0);                 // 1.0 / 3 below 1/3.
  EXPECT_EQ(RoundToDouble(Rational(0.75)), 0.75);
  EXPECT_EQ(RoundToDouble(Rational(0)), 0.0);
  // Just below the next double up: still the one below.
  const double one_up = std::nextafter(1.0, 2.0);
  const Rational almost = Rational(one_up) - Rational(std::ldexp(1.0, -80));
  EXPECT_EQ(RoundToDouble(almost), 1.0);
  EXPECT_EQ(RoundToDouble(-almost), -1.0);
  // Beyond the largest double: the largest double.
  const double largest = std::numeric_limits<double>::max();
  EXPECT_EQ(RoundToDouble(Rational(largest) * 2), largest);
  EXPECT_EQ(RoundToDouble(Rational(largest) * -2), -largest);
  // A lazy number rounds as its exact value does.
  EXPECT_EQ(RoundToDouble(CGAL::Epeck::FT(1) / 10), below_tenth);
}

}  // namespace
}  // namespace acdplan::acd::internal
