#include "acd/component_locator2d.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "acd/decompose2d.h"
#include "acd/read_polygons.h"
#include "base/random.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

/// Inexact even-odd test, trusted only for points well away from every edge.
bool InsideFar(const Polygon2d& polygon, const Point2d& p) {
  bool inside = false;
  auto ring = [&](const Ring2d& r) {
    for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
      if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
          p.x() < r[i].x() + (p.y() - r[i].y()) * (r[j].x() - r[i].x()) / (r[j].y() - r[i].y())) {
        inside = !inside;
      }
    }
  };
  ring(polygon.outer);
  for (const Ring2d& hole : polygon.holes) ring(hole);
  return inside;
}

double DistanceToBoundary(const Polygon2d& polygon, const Point2d& p) {
  double best = INFINITY;
  auto ring = [&](const Ring2d& r) {
    for (size_t i = 0; i < r.size(); ++i) {
      const Point2d a = r[i], b = r[(i + 1) % r.size()];
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (p - (a + t * (b - a))).norm());
    }
  };
  ring(polygon.outer);
  for (const Ring2d& hole : polygon.holes) ring(hole);
  return best;
}

TEST(ComponentLocator2d, AgreesWithABruteForceScanAwayFromTheCuts) {
  const std::vector<Polygon2d> input =
      ReadPolygons(acdplan::test::DataDir() + "/polygons/acd2d/neuron/neuron.poly");
  Decompose2dOptions options;
  options.tau = 0.02 * ReferenceRadius(input[0]);
  const Decomposition2d d = Decompose2d(input, options);
  ASSERT_GT(d.components.size(), 20u);
  const ComponentLocator2d locator(d);

  Eigen::AlignedBox2d box;
  for (const Point2d& p : input[0].outer) box.extend(p);
  const double margin = 1e-7 * box.sizes().norm();
  RandomEngine rng(5);
  int located = 0, outside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point2d p(UniformReal(rng, box.min().x(), box.max().x()),
                    UniformReal(rng, box.min().y(), box.max().y()));
    int expected = -1;
    bool near_a_cut = false;
    for (size_t c = 0; c < d.components.size(); ++c) {
      if (DistanceToBoundary(d.components[c].polygon, p) < margin) near_a_cut = true;
      if (InsideFar(d.components[c].polygon, p)) expected = static_cast<int>(c);
    }
    if (near_a_cut) continue;
    ASSERT_EQ(locator.Locate(p), expected) << "at (" << p.x() << ", " << p.y() << ")";
    (expected < 0 ? outside : located) += 1;
  }
  EXPECT_GT(located, 1000);
  EXPECT_GT(outside, 100);  // the holes and the bounding box's corners
}

TEST(ComponentLocator2d, EmptyDecompositionLocatesNothing) {
  const ComponentLocator2d locator{Decomposition2d{}};
  EXPECT_EQ(locator.Locate(Point2d(0, 0)), -1);
}

TEST(ComponentLocator2d, VerticesAndCutsGoToAnAdjacentComponent) {
  // An L-shape cut at its notch into two rectangles; the cut runs from (1, 1) to (1, 0).
  Decomposition2d d;
  Component2d left, right;
  left.polygon.outer = {{0, 0}, {1, 0}, {1, 1}, {1, 2}, {0, 2}};
  right.polygon.outer = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  d.components = {left, right};
  const ComponentLocator2d locator(d);
  EXPECT_EQ(locator.Locate({0.5, 1.5}), 0);
  EXPECT_EQ(locator.Locate({1.5, 0.5}), 1);
  const int on_cut = locator.Locate({1.0, 0.5});
  EXPECT_TRUE(on_cut == 0 || on_cut == 1) << on_cut;
  EXPECT_EQ(locator.Locate({1.5, 1.5}), -1);
  EXPECT_EQ(locator.Locate({3, 3}), -1);
}

}  // namespace
}  // namespace acdplan::acd
