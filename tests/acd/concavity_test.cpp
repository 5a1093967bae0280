#include "acd/concavity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace acdplan::acd {
namespace {

Polygon2d Square(double side) { return {{{0, 0}, {side, 0}, {side, side}, {0, side}}, {}}; }

// A square with a V-shaped dent in its top edge: the notch (5, 6) lies 4 below the bridge.
Polygon2d DentedSquare() { return {{{0, 0}, {10, 0}, {10, 10}, {5, 6}, {0, 10}}, {}}; }

// A hooked pocket (dissertation Fig. 15): its bridge runs from (8,10) to (0,8); a lip
// (2..6 x 6..8) hides the pocket's far corner (2,2) from the bridge, so the straight line from
// there to the bridge crosses the polygon while the shortest path goes round the lip.
Polygon2d Hook() {
  return {{{0, 0}, {10, 0}, {10, 10}, {8, 10}, {8, 2}, {2, 2}, {2, 6}, {6, 6}, {6, 8}, {0, 8}}, {}};
}

TEST(ConcavityTest, ConvexPolygonHasZeroConcavityAndNoWitness) {
  for (ConcavityMeasure m : {ConcavityMeasure::kStraightLine, ConcavityMeasure::kShortestPath,
                             ConcavityMeasure::kHybrid1, ConcavityMeasure::kHybrid2}) {
    const Concavity2d c = MeasureConcavity(Square(3), {m});
    EXPECT_EQ(c.value, 0.0);
    EXPECT_EQ(c.witness_vertex, -1);
    EXPECT_EQ(c.witness_hole, -1);
    EXPECT_EQ(c.hull.size(), 4u);
  }
}

TEST(ConcavityTest, NotchDepthIsTheDistanceToItsBridge) {
  for (ConcavityMeasure m : {ConcavityMeasure::kStraightLine, ConcavityMeasure::kShortestPath}) {
    const Concavity2d c = MeasureConcavity(DentedSquare(), {m});
    EXPECT_EQ(c.witness_vertex, 3);
    EXPECT_DOUBLE_EQ(c.value, 4.0);
    EXPECT_DOUBLE_EQ(c.outer[3], 4.0);
    EXPECT_EQ(c.outer[0], 0.0);  // On the hull.
  }
}

TEST(ConcavityTest, ShortestPathSeesAroundTheHookWhereStraightLineDoesNot) {
  const Polygon2d hook = Hook();
  const Concavity2d sl = MeasureConcavity(hook, {ConcavityMeasure::kStraightLine});
  const Concavity2d sp = MeasureConcavity(hook, {ConcavityMeasure::kShortestPath});
  const double bridge = std::sqrt(68.0);  // |(8,10) - (0,8)|
  // SL: perpendicular distances to the bridge line; the deepest notch is (8,2).
  EXPECT_NEAR(sl.outer[5], 52.0 / bridge, 1e-12);
  EXPECT_EQ(sl.witness_vertex, 4);
  EXPECT_NEAR(sl.value, 64.0 / bridge, 1e-12);
  // SP from (2,2): to the lip's corner (6,6), up its side to (6,8), then straight to the bridge.
  EXPECT_NEAR(sp.outer[5], 4.0 * std::sqrt(2.0) + 2.0 + 12.0 / bridge, 1e-9);
  EXPECT_EQ(sp.witness_vertex, 5);
  // (8,2) sees the bridge straight on: SP equals SL there.
  EXPECT_NEAR(sp.outer[4], sl.outer[4], 1e-9);
  for (size_t i = 0; i < hook.outer.size(); ++i) EXPECT_LE(sl.outer[i], sp.outer[i] + 1e-12);
}

TEST(ConcavityTest, Hybrid1EqualsShortestPathAndHybrid2FollowsTau) {
  const Polygon2d hook = Hook();
  const Concavity2d sp = MeasureConcavity(hook, {ConcavityMeasure::kShortestPath});
  const Concavity2d h1 = MeasureConcavity(hook, {ConcavityMeasure::kHybrid1});
  EXPECT_EQ(sp.outer, h1.outer);
  const Concavity2d sl = MeasureConcavity(hook, {ConcavityMeasure::kStraightLine});
  // Algorithm 4: SL exceeds a small tau, so H2 keeps SL; with a tau above SL, H2 checks SP.
  ConcavityOptions small{ConcavityMeasure::kHybrid2, HoleDiameter::kAuto, 0.5 * sl.value};
  EXPECT_EQ(MeasureConcavity(hook, small).outer, sl.outer);
  ConcavityOptions large{ConcavityMeasure::kHybrid2, HoleDiameter::kAuto, 2.0 * sl.value};
  EXPECT_EQ(MeasureConcavity(hook, large).outer, sp.outer);
}

TEST(ConcavityTest, HoleConcavityFollowsEquation42) {
  Polygon2d p = Square(10);
  p.holes = {{{3, 4.5}, {3, 5.5}, {7, 5.5}, {7, 4.5}}};  // 4 x 1 rectangle, clockwise.
  const Concavity2d c =
      MeasureConcavity(p, {ConcavityMeasure::kStraightLine, HoleDiameter::kPrincipalAxis});
  ASSERT_EQ(c.holes.size(), 1u);
  const HoleConcavity& h = c.holes[0];
  const Point2d a = p.holes[0][h.p], b = p.holes[0][h.cw_p];
  // The principal axis is x: the antipodes are a left and a right vertex.
  EXPECT_NEAR(std::abs(a.x() - b.x()), 4.0, 1e-12);
  EXPECT_NEAR(h.diameter, (a - b).norm(), 1e-12);
  // The outer ring is convex (delta = 0, concavity(x) = 0): depth = distance to the closest
  // corner of the outer square.
  double closest = 1e9;
  for (const Point2d& corner : p.outer) closest = std::min(closest, (corner - a).norm());
  EXPECT_NEAR(h.depth, closest, 1e-12);
  EXPECT_NEAR(h.concavity, h.depth + h.diameter, 1e-12);
  EXPECT_EQ(c.witness_hole, 0);
  EXPECT_DOUBLE_EQ(c.value, h.concavity);
}

TEST(ConcavityTest, GeodesicDiameterFollowsAWindingHole) {
  // A U-shaped hole (Fig. 20 with one turn): its principal-axis antipodes are about 8 apart,
  // but a path inside the hole between its two prong tips is about twice as long.
  Polygon2d p = Square(20);
  Ring2d u = {{2, 2}, {10, 2}, {10, 10}, {8, 10}, {8, 4}, {4, 4}, {4, 10}, {2, 10}};  // CCW
  p.holes = {Reversed(u)};
  const Concavity2d pa =
      MeasureConcavity(p, {ConcavityMeasure::kShortestPath, HoleDiameter::kPrincipalAxis});
  const Concavity2d geo =
      MeasureConcavity(p, {ConcavityMeasure::kShortestPath, HoleDiameter::kGeodesic});
  EXPECT_GT(geo.holes[0].diameter, pa.holes[0].diameter + 4.0);
  EXPECT_GT(geo.holes[0].concavity, pa.holes[0].concavity);
}

TEST(ConcavityTest, DeeperHolesAreReachedThroughShallowerOnes) {
  // Two holes in a row from the left wall: the right one's closest vertex is on the left one,
  // so its concavity includes the left hole's concavity (Eqn. 4.2, Fig. 23).
  Polygon2d p;
  p.outer = {{0, 0}, {60, 0}, {60, 40}, {0, 40}, {0, 20}};
  p.holes = {Reversed({{1, 19}, {25, 19}, {25, 21}, {1, 21}}),
             Reversed({{26, 19}, {34, 19}, {34, 21}, {26, 21}})};
  const Concavity2d c =
      MeasureConcavity(p, {ConcavityMeasure::kStraightLine, HoleDiameter::kPrincipalAxis});
  EXPECT_NEAR(c.holes[1].depth, c.holes[0].concavity + 1.0, 1e-9);
  EXPECT_LT(c.holes[0].concavity, c.holes[1].concavity);
  EXPECT_EQ(c.witness_hole, 1);
}

TEST(ConcavityTest, IsNotchIgnoresRoundingNoiseButNotRealDents) {
  EXPECT_FALSE(IsNotch({0, 0}, {1, 0}, {2, 0}));         // Collinear.
  EXPECT_FALSE(IsNotch({0, 0}, {1, -1}, {2, 0}));        // Left turn: convex.
  EXPECT_TRUE(IsNotch({0, 0}, {1, 1}, {2, 0}));          // Right turn: a notch.
  EXPECT_TRUE(IsNotch({0, 0}, {1, 1e-6}, {2, 0}));       // A small but real dent.
  EXPECT_FALSE(IsNotch({0, 0}, {1e6, 1e-8}, {2e6, 0}));  // Rounding noise at 1e6.
}

TEST(ConcavityTest, HullIndicesSkipVerticesOnHullEdges) {
  const Ring2d ring = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
  EXPECT_EQ(ConvexHullIndices(ring), (std::vector<int>{0, 2, 3, 5}));
  const Ring2d cloud = {{1, 1}, {0, 0}, {2, 2}, {2, 0}, {0, 2}, {1, 0}};
  const Ring2d hull = ConvexHull(cloud);
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_DOUBLE_EQ(SignedArea(hull), 4.0);
}

// A vertex on a bridge splits its gap into two pockets, each measured against its own part of
// the bridge: (1.5, 1) lies 1 below the whole bridge (4,2)-(0,2), but its pocket's bridge ends
// at (2, 2), which is sqrt(1.25) away.
TEST(ConcavityTest, PocketsSplitAtVerticesOnTheirBridge) {
  const Polygon2d p = {{{0, 0}, {4, 0}, {4, 2}, {1.5, 1}, {2, 2}, {0.5, 1}, {0, 2}}, {}};
  for (ConcavityMeasure m : {ConcavityMeasure::kStraightLine, ConcavityMeasure::kHybrid2}) {
    const Concavity2d c = MeasureConcavity(p, {m});
    EXPECT_DOUBLE_EQ(c.outer[3], std::sqrt(1.25));
    EXPECT_EQ(c.outer[4], 0.0);
    EXPECT_DOUBLE_EQ(c.outer[5], 1.0);
    EXPECT_EQ(c.witness_vertex, 3);
  }
}

// Two notches 4 deep: the witness is the first in ring order, wherever the ring starts.
TEST(ConcavityTest, WitnessIsTheFirstOfEqualNotches) {
  const Polygon2d w = {{{0, 0}, {10, 0}, {10, 10}, {7.5, 6}, {5, 10}, {2.5, 6}, {0, 10}}, {}};
  EXPECT_EQ(MeasureConcavity(w).witness_vertex, 3);
  const Polygon2d turned = {{{5, 10}, {2.5, 6}, {0, 10}, {0, 0}, {10, 0}, {10, 10}, {7.5, 6}}, {}};
  const Concavity2d c = MeasureConcavity(turned);
  EXPECT_EQ(c.witness_vertex, 1);
  EXPECT_DOUBLE_EQ(c.value, 4.0);
}

// Star-shaped rings (simple: vertices by angle around the origin, random radii) with many
// notches, and with the midpoint of every third edge added (exactly collinear: coordinates
// are multiples of 1/1024): ConvexHullIndices() (Melkman's hull of the ring) picks the
// points of CGAL's hull of the same points, never a point on a hull edge.
TEST(ConcavityTest, HullIndicesMatchThePointSetHullOnStarRings) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state]() {  // xorshift64: the same sequence with every standard library.
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
  };
  auto snap = [](double x) { return std::round(x * 1024.0) / 1024.0; };
  constexpr double kPi = 3.14159265358979323846;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 4 + static_cast<int>(next() % 60);
    Ring2d ring;
    for (int i = 0; i < n; ++i) {
      const double angle = 2.0 * kPi * (i + 0.8 * static_cast<double>(next() % 1000) / 1000.0) / n;
      const double radius = 2.0 + 8.0 * static_cast<double>(next() % 1000) / 1000.0;
      const Point2d p(snap(radius * std::cos(angle)), snap(radius * std::sin(angle)));
      if (ring.empty() || p != ring.back()) ring.push_back(p);
    }
    if (trial % 2 == 1) {  // Midpoints, exact.
      Ring2d with_midpoints;
      for (size_t i = 0; i < ring.size(); ++i) {
        with_midpoints.push_back(ring[i]);
        if (i % 3 == 0) with_midpoints.push_back(0.5 * (ring[i] + ring[(i + 1) % ring.size()]));
      }
      ring = with_midpoints;
    }
    std::vector<std::pair<double, double>> melkman, cgal;
    for (const int i : ConvexHullIndices(ring)) melkman.emplace_back(ring[i].x(), ring[i].y());
    for (const Point2d& p : ConvexHull(ring)) cgal.emplace_back(p.x(), p.y());
    std::sort(melkman.begin(), melkman.end());
    std::sort(cgal.begin(), cgal.end());
    EXPECT_EQ(melkman, cgal) << "trial " << trial;
  }
}

TEST(ConcavityTest, CountNotchesCountsHoleVerticesPointingIntoThePolygon) {
  Polygon2d p = Square(10);
  EXPECT_EQ(CountNotches(p), 0);
  p.holes = {Reversed({{4, 4}, {6, 4}, {6, 6}, {4, 6}})};
  EXPECT_EQ(CountNotches(p), 4);  // Every corner of a convex hole is reflex for the polygon.
  EXPECT_EQ(CountNotches(DentedSquare()), 1);
}

}  // namespace
}  // namespace acdplan::acd
