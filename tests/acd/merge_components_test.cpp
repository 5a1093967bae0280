#include "acd/internal/merge_components.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/internal/solid_openings.h"
#include "acd/mesh_measures.h"
#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

using test::Box;

// One root cut by `plane` into the leaves `boxes` (in order).
Decomposition3d Leaves(const std::vector<TriangleMesh>& boxes, const Plane3d& plane, double tau) {
  std::vector<Component3d> components;
  for (const TriangleMesh& box : boxes) {
    components.push_back(SolidComponent(box, MeasureSolidConcavity(box, tau), 0));
  }
  Decomposition3d d = test::OneCut(plane, std::move(components));
  d.tau = tau;
  return d;
}

Plane3d PlaneX(double offset) { return {Eigen::Vector3d::UnitX(), offset}; }

TEST(MergeComponents, TwoBoxesOnOneFaceBecomeTheirBox) {
  // Cut apart by x = 1 with the same section triangles on both sides: the glue path.
  Decomposition3d d =
      Leaves({Box({0, 0, 0}, {1, 1, 1}), Box({1, 0, 0}, {2, 1, 1})}, PlaneX(1), 0.1);
  ASSERT_EQ(d.openings.size(), 1u);
  EXPECT_EQ(MergeComponents(0.1, 0.01, &d), 1);
  ASSERT_EQ(d.components.size(), 1u);
  const Component3d& c = d.components[0];
  EXPECT_TRUE(test::IsClosed(c.mesh));
  EXPECT_NEAR(c.volume, 2.0, 1e-12);
  EXPECT_NEAR(c.hull_volume, 2.0, 1e-12);
  EXPECT_NEAR(c.concavity, 0.0, 1e-12);
  EXPECT_TRUE(c.centroid.isApprox(Eigen::Vector3d(1, 0.5, 0.5), 1e-12));
  EXPECT_EQ(d.tree[1].component, 0);
  EXPECT_EQ(d.tree[2].component, 0);
  EXPECT_TRUE(d.openings.empty());
}

TEST(MergeComponents, AnLMergesOnlyWhenItsConcavityAndHullGrowthAreAllowed) {
  // [0,2]x[0,1]x[0,1] and the post [0,1]x[1,2]x[0,1] on half of its top face: their faces in
  // y = 1 differ, so the union is formed by corefinement. The L's hull is 3.5 against the boxes'
  // 3 (growth 1/6), and its notch edge lies 1/sqrt(2) below the hull's slanted face.
  const std::vector<TriangleMesh> boxes = {Box({0, 0, 0}, {2, 1, 1}), Box({0, 1, 0}, {1, 2, 1})};
  const Plane3d y1{Eigen::Vector3d::UnitY(), 1.0};
  for (const auto& [tau, growth, merges] :
       std::vector<std::tuple<double, double, int>>{{1.0, 0.01, 0}, {0.5, 1.0, 0}, {1.0, 0.2, 1}}) {
    Decomposition3d d = Leaves(boxes, y1, tau);
    ASSERT_EQ(d.openings.size(), 1u);
    EXPECT_EQ(MergeComponents(tau, growth, &d), merges) << "tau " << tau << " growth " << growth;
    ASSERT_EQ(d.components.size(), static_cast<size_t>(2 - merges));
    if (merges == 1) {
      const Component3d& c = d.components[0];
      EXPECT_TRUE(test::IsClosed(c.mesh));
      EXPECT_NEAR(c.volume, 3.0, 1e-12);
      EXPECT_NEAR(MeshVolume(c.mesh), 3.0, 1e-12);
      EXPECT_NEAR(c.hull_volume, 3.5, 1e-12);
      EXPECT_NEAR(c.concavity, 1 / std::sqrt(2.0), 1e-9);
      EXPECT_TRUE(d.openings.empty());
    }
  }
}

TEST(MergeComponents, AMergedComponentMergesOn) {
  // Four unit boxes in a row, cut by x = 2 at the root and x = 1, x = 3 below it: the bar they
  // make is convex, so they all merge, one pair at a time, into one component that every leaf
  // points to.
  Decomposition3d d;
  d.tau = 0.1;
  d.roots = {0};
  auto add = [&d](int parent, const Plane3d& plane) {
    HierarchyNode3d node;
    node.parent = parent;
    node.cut = plane;
    if (parent >= 0)
      d.tree[static_cast<size_t>(parent)].children.push_back(static_cast<int>(d.tree.size()));
    d.tree.push_back(node);
    return static_cast<int>(d.tree.size()) - 1;
  };
  add(-1, PlaneX(2));
  const int left = add(0, PlaneX(1)), right = add(0, PlaneX(3));
  for (int i = 0; i < 4; ++i) {
    const int leaf = add(i < 2 ? left : right, Plane3d{});
    d.tree[static_cast<size_t>(leaf)].component = i;
    const TriangleMesh box = Box({double(i), 0, 0}, {i + 1.0, 1, 1});
    d.components.push_back(SolidComponent(box, MeasureSolidConcavity(box, d.tau), 0));
  }
  ComputeOpenings(&d);
  ASSERT_EQ(d.openings.size(), 3u);
  EXPECT_EQ(MergeComponents(d.tau, 0.0, &d), 3);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_NEAR(d.components[0].volume, 4.0, 1e-12);
  EXPECT_NEAR(d.components[0].hull_volume, 4.0, 1e-12);
  EXPECT_TRUE(test::IsClosed(d.components[0].mesh));
  for (const HierarchyNode3d& node : d.tree) {
    if (node.children.empty()) {
      EXPECT_EQ(node.component, 0);
    }
  }
  EXPECT_TRUE(d.openings.empty());
}

TEST(MergeComponents, ANegativeGrowthMergesNothing) {
  Decomposition3d d =
      Leaves({Box({0, 0, 0}, {1, 1, 1}), Box({1, 0, 0}, {2, 1, 1})}, PlaneX(1), 0.1);
  EXPECT_EQ(MergeComponents(0.1, -1.0, &d), 0);
  EXPECT_EQ(d.components.size(), 2u);
  EXPECT_EQ(d.openings.size(), 1u);
}

}  // namespace
}  // namespace acdplan::acd::internal
