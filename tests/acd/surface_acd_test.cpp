#include "acd/internal/surface_acd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "acd/check_decomposition3d.h"
#include "tests/acd/problem_lines.h"

namespace acdplan::acd {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A surface over the parameter grid [0, nu] x [0, nv], triangulated (closed in u when
// `wrap_u`, in v when `wrap_v`).
TriangleMesh Grid(int nu, int nv, bool wrap_u, bool wrap_v,
                  const std::function<Eigen::Vector3d(int, int)>& point) {
  const int cu = wrap_u ? nu : nu + 1, cv = wrap_v ? nv : nv + 1;
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < cu; ++i) {
    for (int j = 0; j < cv; ++j) v.push_back(point(i, j));
  }
  auto id = [&](int i, int j) { return (i % cu) * cv + (j % cv); };
  std::vector<Eigen::Vector3i> t;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return MakeTriangleMesh(v, t);
}

PreparedMesh Prepared(const TriangleMesh& mesh, bool open) {
  PreparedMesh prepared;
  prepared.mesh = mesh;
  prepared.parts = {mesh};
  if (open) prepared.defects.boundary_edges = 1;
  return prepared;
}

// Decomposes, checks with CheckDecomposition3d and every component against tau.
Decomposition3d DecomposeAndCheck(const PreparedMesh& input, double tau) {
  const Decomposition3d d = internal::DecomposeSurface(input, tau);
  const DecompositionCheck check = CheckDecomposition3d(input, d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(d.stats.surface);
  EXPECT_EQ(d.roots.size(), input.parts.size());
  for (const Component3d& c : d.components) {
    EXPECT_LE(c.concavity, tau);
    EXPECT_EQ(c.volume, 0.0);
  }
  return d;
}

TriangleMesh Square() {
  return MakeTriangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
}

// The cube [-0.5, 0.5]^3 without its top (z = 0.5) faces.
TriangleMesh OpenBox() {
  const TriangleMesh cube = Cube(1.0);
  std::vector<Eigen::Vector3d> v;
  for (Eigen::Index i = 0; i < cube.vertices.rows(); ++i) v.push_back(cube.vertices.row(i));
  std::vector<Eigen::Vector3i> t;
  for (Eigen::Index f = 0; f < cube.triangles.rows(); ++f) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top &= cube.vertices(cube.triangles(f, k), 2) > 0;
    if (!top) t.push_back(cube.triangles.row(f).transpose());
  }
  return MakeTriangleMesh(v, t);
}

// A profile polyline in the yz-plane extruded along x over [0, 2] in `nx` steps.
TriangleMesh Extrude(const std::vector<Eigen::Vector2d>& profile, int nx) {
  return Grid(nx, static_cast<int>(profile.size()) - 1, false, false, [&](int i, int j) {
    return Eigen::Vector3d(2.0 * i / nx, profile[j].x(), profile[j].y());
  });
}

TEST(SurfaceAcdTest, FlatSquareIsOnePatchWithConcavityZero) {
  const Decomposition3d d = DecomposeAndCheck(Prepared(Square(), true), 0.0);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_EQ(d.components[0].concavity, 0.0);
  EXPECT_EQ(d.components[0].mesh.triangles.rows(), 2);
  EXPECT_TRUE(d.openings.empty());
  EXPECT_TRUE(d.components[0].centroid.isApprox(Eigen::Vector3d(0.5, 0.5, 0.0)));
}

TEST(SurfaceAcdTest, OpenBoxLiesOnItsHullAndIsOnePatch) {
  const Decomposition3d d = DecomposeAndCheck(Prepared(OpenBox(), true), 1e-6);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_NEAR(d.components[0].concavity, 0.0, 1e-12);
  EXPECT_NEAR(d.components[0].hull_volume, 1.0, 1e-12);
}

TEST(SurfaceAcdTest, ClosedCubeSurfaceIsOnePatch) {
  const Decomposition3d d = DecomposeAndCheck(Prepared(Cube(2.0), false), 1e-6);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_EQ(d.components[0].mesh.triangles.rows(), 12);
}

TEST(SurfaceAcdTest, FoldIsOnePatchAndAGrooveIsSplitAlongItsValley) {
  // A "V" of two planar strips: every point lies on the hull whichever way it is folded.
  const TriangleMesh fold = Extrude({{-1, 1}, {0, 0}, {1, 1}}, 4);
  EXPECT_EQ(DecomposeAndCheck(Prepared(fold, true), 1e-6).components.size(), 1u);
  // The same valley between two walls: its bottom lies 1 deep inside the hull.
  const TriangleMesh groove = Extrude({{-1, -1}, {-1, 1}, {0, 0}, {1, 1}, {1, -1}}, 4);
  const Decomposition3d d = DecomposeAndCheck(Prepared(groove, true), 0.1);
  ASSERT_EQ(d.components.size(), 2u);
  EXPECT_NEAR(d.tree[d.roots[0]].concavity, 1.0, 1e-9);
  // The cut runs along the valley: the two patches meet along the bottom line.
  ASSERT_EQ(d.openings.size(), 1u);
  EXPECT_EQ(d.openings[0].polygon.size(), 5u);
  for (const Eigen::Vector3d& p : d.openings[0].polygon) {
    EXPECT_EQ(p.y(), 0.0);
    EXPECT_EQ(p.z(), 0.0);
  }
}

TEST(SurfaceAcdTest, HemisphereShellIsOnePatch) {
  const TriangleMesh shell = Grid(32, 12, true, false, [](int i, int j) {
    const double phi = 2 * kPi * i / 32, theta = 0.5 * kPi * j / 12;
    return Eigen::Vector3d(std::cos(phi) * std::sin(theta), std::sin(phi) * std::sin(theta),
                           -std::cos(theta));
  });
  const Decomposition3d d = DecomposeAndCheck(Prepared(shell, true), 0.02);
  EXPECT_EQ(d.components.size(), 1u);
}

TriangleMesh Torus(int nu, int nv) {
  return Grid(nu, nv, true, true, [&](int i, int j) {
    const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
    return Eigen::Vector3d((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u),
                           std::sin(v));
  });
}

TEST(SurfaceAcdTest, TorusSurfaceSplitsIntoSeveralPatchesThatShareOpenings) {
  const Decomposition3d d = DecomposeAndCheck(Prepared(Torus(32, 16), false), 0.1);
  EXPECT_GE(d.components.size(), 3u);
  EXPECT_GT(d.tree[d.roots[0]].concavity, 0.9);  // The inner equator: 1 below the top.
  EXPECT_FALSE(d.openings.empty());
  // Every component is a leaf, the leaves are in depth-first order.
  int next = 0;
  std::vector<int> stack = {d.roots[0]};
  while (!stack.empty()) {
    const HierarchyNode3d& node = d.tree[stack.back()];
    stack.pop_back();
    if (node.children.empty()) {
      EXPECT_EQ(node.component, next++);
    }
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back(*it);
  }
  EXPECT_EQ(next, static_cast<int>(d.components.size()));
}

TEST(SurfaceAcdTest, SmallerTauGivesMorePatches) {
  const PreparedMesh torus = Prepared(Torus(32, 16), false);
  const size_t coarse = DecomposeAndCheck(torus, 0.5).components.size();
  const size_t fine = DecomposeAndCheck(torus, 0.05).components.size();
  EXPECT_LT(coarse, fine);
}

TEST(SurfaceAcdTest, EveryPartIsDecomposedOnItsOwn) {
  PreparedMesh two = Prepared(Square(), true);
  TriangleMesh far = Torus(16, 8);
  far.vertices.col(0).array() += 10.0;
  two.parts.push_back(far);
  const Decomposition3d d = DecomposeAndCheck(two, 0.2);
  ASSERT_EQ(d.roots.size(), 2u);
  EXPECT_EQ(d.components.front().source, 0);
  EXPECT_EQ(d.components.back().source, 1);
}

TEST(SurfaceAcdTest, SameInputGivesTheSameOutput) {
  const PreparedMesh torus = Prepared(Torus(24, 12), false);
  const Decomposition3d a = internal::DecomposeSurface(torus, 0.1);
  const Decomposition3d b = internal::DecomposeSurface(torus, 0.1);
  ASSERT_EQ(a.components.size(), b.components.size());
  for (size_t i = 0; i < a.components.size(); ++i) {
    EXPECT_EQ(a.components[i].mesh.vertices, b.components[i].mesh.vertices);
    EXPECT_EQ(a.components[i].mesh.triangles, b.components[i].mesh.triangles);
    EXPECT_EQ(a.components[i].concavity, b.components[i].concavity);
  }
  ASSERT_EQ(a.openings.size(), b.openings.size());
  for (size_t i = 0; i < a.openings.size(); ++i) {
    EXPECT_EQ(a.openings[i].polygon, b.openings[i].polygon);
  }
}

}  // namespace
}  // namespace acdplan::acd
