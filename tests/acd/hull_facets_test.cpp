// ConvexHullFacets: every facet is an exactly planar, strictly convex polygon with every point
// of the set on its inner side or in it (exact predicates), and the facets close up.

#include "acd/internal/hull_facets.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

#include "base/random.h"

namespace acdplan::acd::internal {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 ToCgal(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

TEST(ConvexHullFacets, FacetsAreStrictlyConvexSupportingPolygons) {
  RandomEngine rng(3);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Coordinates snapped to a few values: many coplanar and collinear points.
    std::vector<Eigen::Vector3d> points;
    const int n = 6 + static_cast<int>(UniformIndex(rng, 80));
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) p[k] = static_cast<double>(UniformIndex(rng, 5)) / 4;
      points.push_back(p);
    }
    const HullFacets hull = ConvexHullFacets(points, 0.0);
    if (hull.facets.size() < 4) continue;  // flat
    ++checked;
    std::map<std::pair<int, int>, int> edges;
    for (const std::vector<int>& facet : hull.facets) {
      ASSERT_GE(facet.size(), 3u);
      EXPECT_EQ(*std::min_element(facet.begin(), facet.end()), facet[0]);
      const size_t m = facet.size();
      auto corner = [&](size_t i) {
        return ToCgal(hull.vertices[static_cast<size_t>(facet[i % m])]);
      };
      for (size_t i = 0; i < m; ++i) {
        ++edges[{facet[i], facet[(i + 1) % m]}];
        EXPECT_FALSE(CGAL::collinear(corner(i), corner(i + 1), corner(i + 2))) << "trial " << trial;
        EXPECT_TRUE(CGAL::coplanar(corner(0), corner(1), corner(2), corner(i)))
            << "trial " << trial;
      }
      // Counter-clockwise seen from outside: no point of the set on the positive side of
      // (c0, c1, c2), i.e. in front of the facet.
      for (const Eigen::Vector3d& p : points) {
        EXPECT_NE(CGAL::orientation(corner(0), corner(1), corner(2), ToCgal(p)), CGAL::POSITIVE)
            << "trial " << trial << ": a point in front of a facet";
      }
    }
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1) << "trial " << trial;
      EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << "trial " << trial;
    }
  }
  EXPECT_GT(checked, 40);
}

// The corners of a tilted square seen along x (so in (y, z)): points inside it, on its edges and
// repeated are no corners; the order is counter-clockwise in (y, z).
TEST(ConvexCornersAlongAxis, KeepsOnlyTheCornersCounterClockwise) {
  std::vector<Eigen::Vector3d> points;
  auto at = [](double y, double z) { return Eigen::Vector3d(0.5 * y + 0.25 * z, y, z); };
  for (const auto& [y, z] : std::vector<std::pair<double, double>>{
           {0.5, 0.5}, {1, 1}, {0, 0.5}, {0, 0}, {1, 0}, {0.25, 0.75}, {0, 1}, {1, 0}, {0.5, 0}}) {
    points.push_back(at(y, z));
  }
  std::vector<Eigen::Vector3d> corners;  // positions: (1, 0) is there twice, either may be kept
  for (const int i : ConvexCornersAlongAxis(points, 0))
    corners.push_back(points[static_cast<size_t>(i)]);
  EXPECT_EQ(corners, (std::vector<Eigen::Vector3d>{at(0, 0), at(1, 0), at(1, 1), at(0, 1)}));
  // Collinear points: the two ends.
  const std::vector<Eigen::Vector3d> line = {at(0, 0), at(0.5, 0.5), at(1, 1), at(0.25, 0.25)};
  EXPECT_EQ(ConvexCornersAlongAxis(line, 0), (std::vector<int>{0, 2}));
  EXPECT_EQ(ConvexCornersAlongAxis({at(1, 1)}, 0), (std::vector<int>{0}));
}

}  // namespace
}  // namespace acdplan::acd::internal
