// PointTree: its searches see every point a scan would, so nearest-point answers with the
// scan's tie-breaking are exact, on point sets full of ties (small integer lattices, repeated
// points) and split into rings of every length.

#include "acd/internal/point_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "base/random.h"

namespace acdplan::acd::internal {
namespace {

// The closest point to `p` by a scan: lowest squared distance, then lowest id.
std::pair<int, double> ScanClosest(const std::vector<Point2d>& points, const Point2d& p) {
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const double d2 = (points[i] - p).squaredNorm();
    if (d2 < best_d2) {
      best = i;
      best_d2 = d2;
    }
  }
  return {best, best_d2};
}

std::pair<int, double> TreeClosest(const PointTree& tree, const Point2d& p) {
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  double radius = best_d2;
  tree.Search(p, &radius, [&](int id, double d2) {
    if (d2 < best_d2 || (d2 == best_d2 && id < best)) {
      best = id;
      best_d2 = d2;
      radius = std::sqrt(d2);
    }
  });
  return {best, best_d2};
}

TEST(PointTreeTest, EmptyTreeVisitsNothing) {
  const PointTree tree({});
  double radius = std::numeric_limits<double>::infinity();
  int visits = 0;
  tree.Search(Point2d(0, 0), &radius, [&](int, double) { ++visits; });
  EXPECT_EQ(visits, 0);
}

TEST(PointTreeTest, ClosestMatchesAScanWithTies) {
  RandomEngine rng(3);
  for (int trial = 0; trial < 400; ++trial) {
    const int side = 2 + trial % 7;
    const double scale = trial % 2 == 0 ? 1.0 : 1e7;
    std::vector<Point2d> points;
    std::vector<int> ring_begin;
    const int rings = 1 + static_cast<int>(UniformIndex(rng, 6));
    for (int r = 0; r < rings; ++r) {
      ring_begin.push_back(static_cast<int>(points.size()));
      const int n = 1 + static_cast<int>(UniformIndex(rng, 50));
      for (int i = 0; i < n; ++i) {
        points.emplace_back(scale * static_cast<double>(UniformIndex(rng, side)),
                            scale * static_cast<double>(UniformIndex(rng, side)));
      }
    }
    const PointTree tree(points, ring_begin);
    for (int q = 0; q < 20; ++q) {
      const Point2d p(scale * UniformReal(rng, -1.0, side), scale * UniformReal(rng, -1.0, side));
      EXPECT_EQ(TreeClosest(tree, p), ScanClosest(points, p)) << "trial " << trial;
      EXPECT_EQ(TreeClosest(tree, points[q % points.size()]),
                ScanClosest(points, points[q % points.size()]));
    }
  }
}

TEST(PointTreeTest, FixedRadiusVisitsEveryPointWithin) {
  RandomEngine rng(5);
  std::vector<Point2d> points;
  for (int i = 0; i < 2000; ++i) {
    points.emplace_back(UniformReal(rng, 0.0, 100.0), UniformReal(rng, 0.0, 100.0));
  }
  const PointTree tree(points);
  for (int q = 0; q < 50; ++q) {
    const Point2d p(UniformReal(rng, -10.0, 110.0), UniformReal(rng, -10.0, 110.0));
    const double radius = UniformReal(rng, 0.0, 20.0);
    std::vector<bool> seen(points.size(), false);
    double r = radius;
    tree.Search(p, &r, [&](int id, double) { seen[id] = true; });
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      if (std::sqrt((points[i] - p).squaredNorm()) <= radius) {
        EXPECT_TRUE(seen[i]) << i;
      }
    }
  }
}

}  // namespace
}  // namespace acdplan::acd::internal
