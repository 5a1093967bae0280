#include "acd/internal/solid_openings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "base/random.h"
#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

// Only the section faces of a piece: the unit square in z = 0 triangulated by `triangles` (in
// the plane, counter-clockwise), facing +z (`below` the cut) or -z.
TriangleMesh Section(const std::vector<Eigen::Vector2d>& points,
                     const std::vector<Eigen::Vector3i>& triangles, bool below) {
  std::vector<Eigen::Vector3d> vertices;
  for (const Eigen::Vector2d& p : points) vertices.emplace_back(p.x(), p.y(), 0.0);
  std::vector<Eigen::Vector3i> faces;
  for (const Eigen::Vector3i& t : triangles) {
    faces.push_back(below ? t : Eigen::Vector3i(t[0], t[2], t[1]));
  }
  return MakeTriangleMesh(vertices, faces);
}

// Pieces cut apart by z = 0, with only their section faces.
Decomposition3d Pieces(const std::vector<TriangleMesh>& sections) {
  std::vector<Component3d> components(sections.size());
  for (size_t i = 0; i < sections.size(); ++i) components[i].mesh = sections[i];
  return test::OneCut({Eigen::Vector3d::UnitZ(), 0.0}, std::move(components));
}

// Distance from `x` (in z = 0) to the counter-clockwise triangle `t`.
double DistanceToTriangle(const Eigen::Vector3d& x, const std::vector<Eigen::Vector2d>& t) {
  const Eigen::Vector2d p(x.x(), x.y());
  double outside = 0, nearest = 1e300;
  for (size_t k = 0; k < 3; ++k) {
    const Eigen::Vector2d a = t[k], b = t[(k + 1) % 3];
    const Eigen::Vector2d e = b - a;
    if (e.x() * (p - a).y() - e.y() * (p - a).x() < 0) outside = 1;
    const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (a + s * e - p).norm());
  }
  return std::hypot(outside * nearest, x.z());
}

// Above the cut, the square A B C D is a fan around its centre P, and its triangle P Q B (Q on
// A B, delta from B) is a piece of its own: a sliver with its apex at P. Below, the square is
// triangulated with an edge R S from R = (gamma, 1) beside D to S = (1, eta) beside B, which passes
// P at a tiny angle to the sliver's long edges. A rounded crossing of nearly parallel edges can
// slide along them past the sliver's apex, off the sliver (hips.obj at tau_rel 0.02 had an opening
// vertex 4.9e-10 beyond a sliver's apex, off its component). The openings with the sliver must
// stay on it (to 1e-12 of the diagonal), and all openings must cover the square once.
TEST(ComputeOpeningsTest, CrossingsNearASliversApexStayOnTheSliver) {
  RandomEngine rng(3);
  for (int trial = 0; trial < 400; ++trial) {
    const double delta = std::pow(10.0, UniformReal(rng, -12, -4));
    const double gamma = std::pow(10.0, UniformReal(rng, -16, -8));
    const double eta = std::pow(10.0, UniformReal(rng, -16, -8));
    const std::vector<Eigen::Vector2d> upper = {{0, 0}, {1, 0},     {1, 1},
                                                {0, 1}, {0.5, 0.5}, {1 - delta, 0}};
    const TriangleMesh sliver = Section(upper, {{5, 1, 4}}, false);
    const TriangleMesh rest = Section(upper, {{0, 5, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}, false);
    const std::vector<Eigen::Vector2d> lower = {{0, 0}, {1, 0},     {1, 1},
                                                {0, 1}, {gamma, 1}, {1, eta}};
    const TriangleMesh below = Section(lower, {{4, 5, 2}, {0, 1, 5}, {0, 5, 4}, {0, 4, 3}}, true);
    const Decomposition3d d = Pieces({below, sliver, rest});
    double area = 0;
    for (const Opening3d& opening : d.openings) {
      EXPECT_EQ(opening.component_a, 0);
      area += opening.area;
      if (opening.component_b != 1) continue;
      for (const Eigen::Vector3d& x : opening.polygon) {
        EXPECT_LE(DistanceToTriangle(x, {upper[5], upper[1], upper[4]}), 1e-12 * std::sqrt(2.0))
            << "trial " << trial << ": delta " << delta << ", gamma " << gamma << ", eta " << eta
            << ", vertex " << x.transpose();
      }
    }
    EXPECT_NEAR(area, 1.0, 1e-8) << "trial " << trial;  // parts below 1e-10 x 2 are dropped
  }
}

// Below the cut, the square [0, 3]^2 in two triangles; above it, the frame around [1, 2]^2 (8
// triangles) is one piece and the centre square another. The frame's shared region is a ring:
// one opening, its outline and one clockwise hole, not one opening per clipped triangle.
TEST(ComputeOpeningsTest, ARingShapedSharedRegionIsOneOpeningWithAHole) {
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {3, 0}, {3, 3}, {0, 3},
                                               {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Eigen::Vector3i> frame;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    frame.emplace_back(i, j, 4 + j);
    frame.emplace_back(i, 4 + j, 4 + i);
  }
  const Decomposition3d d =
      Pieces({Section(points, {{0, 1, 2}, {0, 2, 3}}, true), Section(points, frame, false),
              Section(points, {{4, 5, 6}, {4, 6, 7}}, false)});
  ASSERT_EQ(d.openings.size(), 2u);
  auto in_plane = [](const std::vector<Eigen::Vector3d>& ring) {
    Ring2d flat;
    for (const Eigen::Vector3d& p : ring) {
      EXPECT_EQ(p.z(), 0.0);
      flat.emplace_back(p.x(), p.y());
    }
    return flat;
  };
  const Opening3d& ring = d.openings[0];
  EXPECT_EQ(ring.component_a, 0);
  EXPECT_EQ(ring.component_b, 1);
  EXPECT_EQ(ring.normal, Eigen::Vector3d::UnitZ());  // From component 0, below, into 1.
  EXPECT_NEAR(ring.area, 8.0, 1e-12);
  const Ring2d outline = in_plane(ring.polygon);
  EXPECT_EQ(outline.size(), 4u);
  EXPECT_NEAR(SignedArea(outline), 9.0, 1e-12);
  ASSERT_EQ(ring.holes.size(), 1u);
  const Ring2d hole = in_plane(ring.holes[0]);
  EXPECT_EQ(hole.size(), 4u);
  EXPECT_NEAR(SignedArea(hole), -1.0, 1e-12);  // Clockwise seen from the normal's tip.

  const Opening3d& centre = d.openings[1];
  EXPECT_EQ(centre.component_b, 2);
  EXPECT_NEAR(centre.area, 1.0, 1e-12);
  EXPECT_TRUE(centre.holes.empty());
  EXPECT_EQ(in_plane(centre.polygon).size(), 4u);

  // For the merge pass: the same pairs, normals and areas, no polygons.
  Decomposition3d adjacency = d;
  ComputeOpenings(&adjacency, OpeningDetail::kAdjacency);
  ASSERT_EQ(adjacency.openings.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const Opening3d& o = adjacency.openings[k];
    EXPECT_EQ(o.component_a, d.openings[k].component_a);
    EXPECT_EQ(o.component_b, d.openings[k].component_b);
    EXPECT_EQ(o.normal, d.openings[k].normal);
    EXPECT_NEAR(o.area, d.openings[k].area, 1e-12);
    EXPECT_TRUE(o.polygon.empty());
  }
}

// An L-shaped shared region (not convex, no hole) is one opening too, its six corners only.
TEST(ComputeOpeningsTest, ANonConvexSharedRegionIsOneOpening) {
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {2, 0}, {2, 1}, {1, 1},
                                               {1, 2}, {0, 2}, {2, 2}};
  // Below: the L as a fan around (1, 1)'s neighbours; above: the L plus the missing square,
  // a different triangulation whose edges cross the first's.
  const TriangleMesh below = Section(points, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}, true);
  const TriangleMesh above =
      Section(points, {{0, 1, 3}, {1, 2, 3}, {0, 3, 5}, {3, 4, 5}, {2, 6, 4}, {2, 4, 3}}, false);
  const Decomposition3d d = Pieces({below, above});
  ASSERT_EQ(d.openings.size(), 1u);
  EXPECT_EQ(d.openings[0].polygon.size(), 6u);
  EXPECT_TRUE(d.openings[0].holes.empty());
  EXPECT_NEAR(d.openings[0].area, 3.0, 1e-12);
}

}  // namespace
}  // namespace acdplan::acd::internal
