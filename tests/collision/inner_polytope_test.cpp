#include "collision/internal/inner_polytope.h"

#include <gtest/gtest.h>

#include <vector>

#include "acd/convex_hull3d.h"
#include "base/random.h"
#include "collision/internal/solid_locator.h"
#include "tests/acd/solid_test_meshes.h"

namespace acdplan::collision::internal {
namespace {

std::vector<Triangle3> Triangles(const acd::TriangleMesh& mesh) {
  std::vector<Triangle3> out;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    Triangle3 t;
    for (int k = 0; k < 3; ++k) t[k] = mesh.vertices.row(mesh.triangles(f, k)).transpose();
    out.push_back(t);
  }
  return out;
}

Eigen::Matrix<double, Eigen::Dynamic, 4> HullPlanesOf(const acd::TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) points.push_back(mesh.vertices.row(i));
  return acd::HullPlanes(acd::ConvexHull3(points, 0.0));
}

constexpr double kMargin = 1e-9;

// The L-block's hull covers its notch; K must leave the notch out and keep most of the block.
TEST(InnerPolytope, LBlockKeepsItsBodyAndLeavesTheNotchOut) {
  const acd::TriangleMesh l = acd::test::LBlock();
  const MeshLocator3d locator(l);
  const ConvexPolytope k =
      InnerPolytope(Triangles(l), HullPlanesOf(l), {0.5, 0.5, 0.5}, kMargin,
                    [&](const Eigen::Vector3d& p) { return locator.ContainsInInterior(p); });
  ASSERT_FALSE(k.planes.empty());
  EXPECT_TRUE(InsideBy(k, {0.2, 0.2, 0.5}, 0));
  EXPECT_FALSE(InsideBy(k, {1.6, 1.6, 0.5}, 0));  // in the notch: inside the hull, outside L
  RandomEngine rng(5);
  int in_k = 0;
  const int samples = 20000;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3d p(UniformReal(rng, 0, 2), UniformReal(rng, 0, 2), UniformReal(rng, 0, 1));
    if (!InsideBy(k, p, 0)) continue;
    ++in_k;
    ASSERT_TRUE(locator.ContainsInInterior(p)) << p.transpose();
  }
  // K is the block below the notch's corner (x + y <= 2): half of the 2 x 2 x 1 box.
  EXPECT_NEAR(static_cast<double>(in_k) / samples, 0.5, 0.02);
}

// A box with a cavity: the cavity's faces move every face of K in to the cavity, so K is the
// cavity, which the inside test rejects; without the cavity, K is the whole box.
TEST(InnerPolytope, ACavityIsNotTakenForInside) {
  const acd::TriangleMesh outer = acd::test::Box({-1, -1, -1}, {1, 1, 1});
  const acd::TriangleMesh cavity = acd::test::Box({-0.3, -0.3, -0.3}, {0.3, 0.3, 0.3}, true);
  auto inside = [](const Eigen::Vector3d& p) {
    const double m = p.cwiseAbs().maxCoeff();
    return m <= 1 && m >= 0.3;
  };
  std::vector<Triangle3> surface = Triangles(outer);
  const std::vector<Triangle3> inner = Triangles(cavity);
  EXPECT_FALSE(
      InnerPolytope(surface, HullPlanesOf(outer), {0, 0, 0}, kMargin, [](const Eigen::Vector3d&) {
        return true;
      }).planes.empty());
  surface.insert(surface.end(), inner.begin(), inner.end());
  EXPECT_TRUE(
      InnerPolytope(surface, HullPlanesOf(outer), {0, 0, 0}, kMargin, inside).planes.empty());
  // A center outside K (beyond the cavity) cannot keep it either.
  EXPECT_TRUE(
      InnerPolytope(surface, HullPlanesOf(outer), {0.6, 0, 0}, kMargin, inside).planes.empty());
}

// Random triangles through and around a cube: none may meet K's interior, and triangles that
// stay outside the cube leave K the whole cube (less the margin).
TEST(InnerPolytope, NoTriangleMeetsItsInterior) {
  const acd::TriangleMesh cube = acd::test::Box({-1, -1, -1}, {1, 1, 1});
  const auto planes = HullPlanesOf(cube);
  auto yes = [](const Eigen::Vector3d&) { return true; };
  const std::vector<Triangle3> outside = {
      {Eigen::Vector3d(1.5, 0, 0), Eigen::Vector3d(3, 1, 0), Eigen::Vector3d(3, -1, 0)}};
  const ConvexPolytope whole = InnerPolytope(outside, planes, {0, 0, 0}, kMargin, yes);
  EXPECT_TRUE(InsideBy(whole, {0.999, 0.999, -0.999}, 0));

  RandomEngine rng(17);
  int kept = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Triangle3> surface;
    for (int t = 0; t < 3; ++t) {
      Triangle3 triangle;
      for (auto& v : triangle) {
        v = Eigen::Vector3d(UniformReal(rng, -2, 2), UniformReal(rng, -2, 2),
                            UniformReal(rng, -2, 2));
      }
      surface.push_back(triangle);
    }
    const ConvexPolytope k = InnerPolytope(surface, planes, {0, 0, 0}, kMargin, yes);
    if (k.planes.empty()) continue;
    ++kept;
    for (const Triangle3& t : surface) {
      for (int s = 0; s < 200; ++s) {
        double a = UniformReal(rng, 0, 1), b = UniformReal(rng, 0, 1);
        if (a + b > 1) {
          a = 1 - a;
          b = 1 - b;
        }
        const Eigen::Vector3d p = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
        ASSERT_FALSE(InsideBy(k, p, 0)) << "trial " << trial << ": " << p.transpose();
      }
    }
  }
  EXPECT_GT(kept, 10);  // the test would be empty if K were never kept
}

}  // namespace
}  // namespace acdplan::collision::internal
