#include "acd/internal/triangulate_ring.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "tests/acd/geodesic_test_polygons.h"

namespace acdplan::acd::internal {
namespace {

using testing::RandomComb;
using testing::RandomSpiral;
using testing::RandomStar;
using testing::RandomTwoOptPolygon;
using testing::RegularPolygon;

double TriangleArea(const Ring2d& ring, const std::array<int, 3>& t) {
  const Point2d u = ring[t[1]] - ring[t[0]], v = ring[t[2]] - ring[t[0]];
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

// Property check of a triangulation: n - 2 triangles of distinct in-range indices, none
// clockwise, areas summing to the ring's area, each ring edge used once and each diagonal once
// in each direction (so the triangles tile the polygon as a triangulation does).
void ExpectValidTriangulation(const Ring2d& ring, const std::string& label) {
  SCOPED_TRACE(label);
  const int n = static_cast<int>(ring.size());
  const std::vector<std::array<int, 3>> tris = TriangulateRing(ring);
  ASSERT_EQ(static_cast<int>(tris.size()), n - 2);
  double area = 0.0;
  std::map<std::pair<int, int>, int> half_edges;
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(t[k], 0);
      ASSERT_LT(t[k], n);
      ++half_edges[{t[k], t[(k + 1) % 3]}];
    }
    ASSERT_NE(t[0], t[1]);
    ASSERT_NE(t[1], t[2]);
    ASSERT_NE(t[0], t[2]);
    EXPECT_GE(Orientation(ring[t[0]], ring[t[1]], ring[t[2]]), 0)
        << "clockwise triangle " << t[0] << " " << t[1] << " " << t[2];
    area += TriangleArea(ring, t);
  }
  EXPECT_NEAR(area, SignedArea(ring), 1e-9 * std::abs(SignedArea(ring)));
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    EXPECT_EQ(half_edges.count({i, j}), 1u) << "ring edge " << i << "-" << j << " unused";
    EXPECT_EQ(half_edges.count({j, i}), 0u) << "ring edge " << i << "-" << j << " reversed";
  }
  for (const auto& [edge, count] : half_edges) {
    EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
    const bool ring_edge = edge.second == (edge.first + 1) % n;
    if (!ring_edge) {
      EXPECT_EQ(half_edges.count({edge.second, edge.first}), 1u)
          << "diagonal " << edge.first << "-" << edge.second << " has no twin";
    }
  }
}

TEST(TriangulateRingTest, Triangle) {
  const Ring2d tri = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(TriangulateRing(tri), (std::vector<std::array<int, 3>>{{0, 1, 2}}));
}

TEST(TriangulateRingTest, Convex) {
  for (int n : {4, 5, 17, 200})
    ExpectValidTriangulation(RegularPolygon(n), "n=" + std::to_string(n));
}

TEST(TriangulateRingTest, ConvexWithCollinearVertices) {
  Ring2d square;
  for (int i = 0; i < 5; ++i) square.emplace_back(i, 0);
  for (int i = 0; i < 5; ++i) square.emplace_back(5, i);
  for (int i = 5; i > 0; --i) square.emplace_back(i, 5);
  for (int i = 5; i > 0; --i) square.emplace_back(0, i);
  ExpectValidTriangulation(square, "square with 4 vertices per side");
  // A long thin rectangle with many points on both long sides.
  Ring2d bar;
  for (int i = 0; i <= 300; ++i) bar.emplace_back(i, 0);
  for (int i = 300; i >= 0; --i) bar.emplace_back(i, 1);
  ExpectValidTriangulation(bar, "bar");
}

TEST(TriangulateRingTest, CollinearReflexVertices) {
  // An L with vertices along both arms' inner sides, including the reflex corner's lines.
  const Ring2d ell = {{0, 0}, {2, 0}, {4, 0}, {4, 1}, {3, 1}, {2, 1},
                      {1, 1}, {1, 2}, {1, 3}, {1, 4}, {0, 4}, {0, 2}};
  ExpectValidTriangulation(ell, "L shape");
  RandomEngine rng(7);
  for (int i = 0; i < 20; ++i) {
    ExpectValidTriangulation(RandomComb(3 + i, rng), "comb " + std::to_string(i));
  }
}

TEST(TriangulateRingTest, CombSpiralStarTwoOpt) {
  RandomEngine rng(11);
  for (int i = 0; i < 20; ++i) {
    ExpectValidTriangulation(RandomComb(2 + i, rng, /*jitter=*/true), "comb " + std::to_string(i));
    ExpectValidTriangulation(RandomSpiral(0.5 + 0.37 * i, rng), "spiral " + std::to_string(i));
    ExpectValidTriangulation(RandomStar(5 + 50 * i, rng, 0.05), "star " + std::to_string(i));
    ExpectValidTriangulation(RandomTwoOptPolygon(5 + 2 * i, rng), "2-opt " + std::to_string(i));
  }
  ExpectValidTriangulation(RandomStar(5000, rng, 0.05), "star 5000");
}

TEST(TriangulateRingTest, ExtremeAspectRatios) {
  // Combs with 20 reflex vertices, 1e30 times wider than high and the other way round: the
  // reflex-vertex grid's cell counts once overflowed an int (found by fuzz_mesh_reader).
  for (const double scale : {1e30, 1e-30}) {
    Ring2d comb = {{0, 0}, {21, 0}, {21, 2}};
    for (int k = 20; k >= 1; --k) comb.insert(comb.end(), {{k + 0.5, 2}, {k + 0.25, 1}, {k, 2}});
    comb.push_back({0, 2});
    for (Point2d& p : comb) p.x() *= scale;
    ExpectValidTriangulation(comb, "scale " + std::to_string(scale));
  }
}

TEST(TriangulateRingTest, WeaklySimpleRings) {
  // Two squares touching at a repeated vertex (1, 1).
  const Ring2d bowtie = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}};
  ExpectValidTriangulation(bowtie, "squares sharing a corner");
  // A square hole joined to the outer square by a doubled bridge edge (0,0)-(1,1).
  const Ring2d keyhole = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0},
                          {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}};
  ExpectValidTriangulation(keyhole, "square with a bridged hole");
  // A zero-width antenna (a spike out and back along the same segment).
  const Ring2d antenna = {{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 3}, {1, 2}, {0, 2}};
  ExpectValidTriangulation(antenna, "antenna");
}

TEST(TriangulateRingTest, RejectsTooFewVertices) {
  try {
    TriangulateRing({{0, 0}, {1, 0}});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "TriangulateRing(): the ring needs at least 3 vertices, got 2");
  }
}

}  // namespace
}  // namespace acdplan::acd::internal
