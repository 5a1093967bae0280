// acd/internal/exact_predicates.h: both orientation forms must return CGAL's exact sign, also
// where rounding decides it (points on or next to a line, far from the origin).
#include "acd/internal/exact_predicates.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

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

}  // namespace
}  // namespace acdplan::acd::internal
