// EdgeGrid::AnyNear: every edge that comes within the pad of the segment is reported, none
// twice, and the walk stops at the first edge the visitor takes; checked against a scan of all
// edges on random rings with long edges (coarse grids), clusters, and coordinates far from 0.

#include "acd/internal/edge_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "base/random.h"
#include "tests/polygon_fixtures.h"

namespace acdplan::acd::internal {
namespace {

double PointSegmentDistance(const Point2d& p, const Point2d& a, const Point2d& b) {
  const Point2d ab = b - a;
  const double s = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + s * ab - p).norm();
}

// Whether the segments a-b and c-d cross clearly (strict turns, far from zero).
bool ClearlyCross(const Point2d& a, const Point2d& b, const Point2d& c, const Point2d& d) {
  auto turn = [](const Point2d& p, const Point2d& q, const Point2d& r) {
    const Point2d u = q - p, v = r - p;
    const double det = u.x() * v.y() - u.y() * v.x();
    const double scale = u.norm() * v.norm();
    return det > 1e-6 * scale ? 1 : det < -1e-6 * scale ? -1 : 0;
  };
  const int t1 = turn(a, b, c), t2 = turn(a, b, d), t3 = turn(c, d, a), t4 = turn(c, d, b);
  return t1 * t2 < 0 && t3 * t4 < 0;
}

TEST(EdgeGridTest, AnyNearReportsEveryNearEdgeOnce) {
  RandomEngine rng(21);
  const std::vector<std::pair<Point2d, double>> frames = {
      {Point2d(0.0, 0.0), 1.0}, {Point2d(1e6, -3e6), 1.0}, {Point2d(-1e9, 1e9), 0.5}};
  for (int trial = 0; trial < 300; ++trial) {
    // Plain copies, not structured bindings: C++17 lambdas cannot capture those.
    const Point2d origin = frames[trial % frames.size()].first;
    const double step = frames[trial % frames.size()].second;
    const Polygon2d polygon = acdplan::test::RandomRings(rng, origin, step, false);
    const EdgeGrid grid(polygon);
    for (int q = 0; q < 10; ++q) {
      auto anywhere = [&]() {
        return Point2d(origin +
                       step * Point2d(UniformReal(rng, -5.0, 40.0), UniformReal(rng, -5.0, 40.0)));
      };
      // From a vertex (as the cuts do) or from anywhere, to anywhere.
      const Point2d a =
          q % 2 == 0 ? polygon.outer[UniformIndex(rng, polygon.outer.size())] : anywhere();
      const Point2d b = anywhere();
      const double pad = q % 3 == 0 ? 0.0 : UniformReal(rng, 0.0, 2.0) * step;
      std::vector<std::vector<int>> seen(polygon.holes.size() + 1);
      for (size_t k = 0; k < seen.size(); ++k) {
        seen[k].assign(k == 0 ? polygon.outer.size() : polygon.holes[k - 1].size(), 0);
      }
      const bool stopped = grid.AnyNear(a, b, pad, [&](const EdgeGrid::Edge& e) {
        ++seen[e.ring + 1][e.index];
        return false;
      });
      EXPECT_FALSE(stopped);
      for (int ring = -1; ring < static_cast<int>(polygon.holes.size()); ++ring) {
        const Ring2d& points = ring < 0 ? polygon.outer : polygon.holes[ring];
        const int m = static_cast<int>(points.size());
        for (int i = 0; i < m; ++i) {
          ASSERT_LE(seen[ring + 1][i], 1) << "trial " << trial << ": edge reported twice";
          const Point2d& u = points[i];
          const Point2d& w = points[(i + 1) % m];
          // Clearly near: within 0.99 pad of the segment, or clearly across it.
          const double distance =
              std::min({PointSegmentDistance(u, a, b), PointSegmentDistance(w, a, b),
                        PointSegmentDistance(a, u, w), PointSegmentDistance(b, u, w)});
          if (distance < 0.99 * pad || ClearlyCross(a, b, u, w)) {
            ASSERT_EQ(seen[ring + 1][i], 1)
                << "trial " << trial << " query " << q << ": ring " << ring << " edge " << i
                << " is near the segment and was not reported";
          }
        }
      }
    }
  }
}

TEST(EdgeGridTest, AnyNearStopsAtTheFirstEdgeTaken) {
  RandomEngine rng(22);
  for (int trial = 0; trial < 100; ++trial) {
    const Polygon2d polygon = acdplan::test::RandomRings(rng, Point2d(2.0, 7.0), 3.0, false);
    const EdgeGrid grid(polygon);
    const Point2d a = polygon.outer.front();
    const Point2d b = polygon.outer[polygon.outer.size() / 2];
    int reported = 0;
    int total = 0;
    grid.AnyNear(a, b, 0.0, [&](const EdgeGrid::Edge&) { return ++total, false; });
    const int stop_at = 1 + static_cast<int>(UniformIndex(rng, total));
    const bool stopped =
        grid.AnyNear(a, b, 0.0, [&](const EdgeGrid::Edge&) { return ++reported == stop_at; });
    EXPECT_TRUE(stopped);
    EXPECT_EQ(reported, stop_at);
  }
}

}  // namespace
}  // namespace acdplan::acd::internal
