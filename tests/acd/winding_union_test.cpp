#include "acd/internal/winding_union.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "acd/internal/face_intersections.h"
#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/random.h"
#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<int> AllFaces(const TriangleMesh& mesh) {
  std::vector<int> faces(static_cast<size_t>(mesh.triangles.rows()));
  std::iota(faces.begin(), faces.end(), 0);
  return faces;
}

std::optional<WindingUnion> Unite(const TriangleMesh& mesh) {
  return UniteByWinding(mesh, AllFaces(mesh), IntersectingFacePairs(mesh));
}

// The generalized winding number of `mesh` at p: the triangles' signed solid angles / 4 pi
// (van Oosterom and Strackee), an independent way to tell w from the rays UniteByWinding casts.
double Winding(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double sum = 0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0)).transpose() - p;
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1)).transpose() - p;
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2)).transpose() - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2 * std::atan2(a.dot(b.cross(c)),
                          la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return sum / (4 * kPi);
}

// A square tube [r1, r2] x [0, height] swept about the z axis by `turns` x 2 pi in `steps`
// steps, rising by `rise` per turn, with its two ends capped: one closed, outward shell. With
// more than one turn it overlaps itself.
TriangleMesh SweptTube(double turns, int steps, double rise) {
  const double r1 = 1, r2 = 2, height = 1;
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i <= steps; ++i) {
    const double t = turns * i / steps;
    const double angle = 2 * kPi * t, z = rise * t;
    for (const auto& [r, h] : {std::pair{r1, 0.0}, {r2, 0.0}, {r2, height}, {r1, height}}) {
      v.emplace_back(r * std::cos(angle), r * std::sin(angle), z + h);
    }
  }
  std::vector<Eigen::Vector3i> t;
  for (int i = 0; i < steps; ++i) {
    for (int k = 0; k < 4; ++k) {
      const int a = 4 * i + k, b = 4 * i + (k + 1) % 4, c = b + 4, d = a + 4;
      t.emplace_back(a, b, c);
      t.emplace_back(a, c, d);
    }
  }
  const int last = 4 * steps;
  t.emplace_back(0, 2, 1);
  t.emplace_back(0, 3, 2);
  t.emplace_back(last, last + 1, last + 2);
  t.emplace_back(last, last + 2, last + 3);
  TriangleMesh mesh = MakeTriangleMesh(v, t);
  if (MeshVolume(mesh) < 0) mesh.triangles.col(1).swap(mesh.triangles.col(2));
  return mesh;
}

// Checks that `solid` is the positive-winding region of `shells` at random points of their box:
// its own winding number is 0 or 1, and 1 exactly where that of `shells` is > 0. Points within
// 1e-6 of an integer winding of `shells` are skipped (they lie on its surface).
void ExpectPositiveWindingRegion(const TriangleMesh& shells, const TriangleMesh& solid) {
  const Eigen::AlignedBox3d box = BoundingBox(shells);
  RandomEngine rng(7);
  int checked = 0, positive = 0;
  for (int i = 0; i < 600; ++i) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p(k) = UniformReal(rng, box.min()(k), box.max()(k));
    const double w = Winding(shells, p);
    if (std::abs(w - std::round(w)) > 1e-6) continue;
    const double u = Winding(solid, p);
    ASSERT_NEAR(u, std::round(u), 1e-6) << p.transpose();
    EXPECT_EQ(std::lround(u), std::lround(w) > 0 ? 1 : 0) << p.transpose() << " w = " << w;
    ++checked;
    positive += std::lround(w) > 0;
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(positive, 50);
}

TEST(UniteByWindingTest, KeepsAShellThatDoesNotCrossItself) {
  const TriangleMesh cube = test::Box({0, 0, 0}, {1, 1, 1});
  const auto united = UniteByWinding(cube, AllFaces(cube), {});
  ASSERT_TRUE(united);
  EXPECT_EQ(united->mesh.triangles.rows(), 12);
  EXPECT_EQ(united->pinches, 0);
  EXPECT_DOUBLE_EQ(MeshVolume(united->mesh), 1.0);
}

TEST(UniteByWindingTest, TwoCrossingCubesBecomeTheirUnion) {
  const TriangleMesh cubes =
      test::Concatenate(test::Box({0, 0, 0}, {2, 2, 2}), test::Box({1, 1, 1}, {3, 3, 3}));
  const auto united = Unite(cubes);
  ASSERT_TRUE(united);
  EXPECT_NEAR(MeshVolume(united->mesh), 8 + 8 - 1, 1e-12);
  EXPECT_TRUE(PrepareMesh(united->mesh).solid());
  ExpectPositiveWindingRegion(cubes, united->mesh);
}

TEST(UniteByWindingTest, ATubeThatWindsOverItsFirstTurnBecomesTheSolidItWindsAround) {
  // One and a quarter turns, rising by half its height per turn: the last quarter crosses the
  // first one's top and caps.
  const TriangleMesh tube = SweptTube(1.25, 40, 0.5);
  ASSERT_FALSE(PrepareMesh(tube).solid());
  const auto united = Unite(tube);
  ASSERT_TRUE(united);
  // Closed; whether it is also free of crossings once rounded is for the caller to check (here
  // two slivers at the crossing curves do cross after rounding).
  EXPECT_TRUE(test::IsClosed(united->mesh));
  EXPECT_EQ(PrepareMesh(united->mesh).defects.boundary_edges, 0);
  EXPECT_EQ(PrepareMesh(united->mesh).defects.non_manifold_edges, 0);
  EXPECT_LT(MeshVolume(united->mesh), MeshVolume(tube));  // The overlap counts once.
  ExpectPositiveWindingRegion(tube, united->mesh);
}

TEST(UniteByWindingTest, CopiesOfTheSameTrianglesCountOnce) {
  // The second turn runs over the first exactly (the same vertex positions, new vertex
  // numbers): their faces overlap in their planes. The solid is the ring, each of its faces once.
  const int steps_per_turn = 24;
  const TriangleMesh tube = SweptTube(1.25, steps_per_turn * 5 / 4, 0.0);
  const auto united = Unite(tube);
  ASSERT_TRUE(united);
  EXPECT_TRUE(test::IsClosed(united->mesh));
  // A ring of height 1 between two regular 24-gons of circumradius 1 and 2.
  const double ring = 0.5 * steps_per_turn * std::sin(2 * kPi / steps_per_turn) * (4 - 1);
  EXPECT_NEAR(MeshVolume(united->mesh), ring, 1e-9);
  ExpectPositiveWindingRegion(tube, united->mesh);
}

TEST(UniteByWindingTest, CubesThatTouchAtACornerGetACornerEach) {
  // The union of two cubes that meet in one point is not a 2-manifold there: each keeps its own
  // copy of the corner, moved a hair into its own cube.
  const TriangleMesh cubes =
      test::Concatenate(test::Box({0, 0, 0}, {1, 1, 1}), test::Box({1, 1, 1}, {2, 2, 2}));
  const auto united = Unite(cubes);
  ASSERT_TRUE(united);
  EXPECT_EQ(united->pinches, 1);
  EXPECT_EQ(united->mesh.vertices.rows(), 16);
  EXPECT_NEAR(MeshVolume(united->mesh), 2.0, 1e-3);  // Each corner moved by 1e-3.
  const PreparedMesh prepared = PrepareMesh(united->mesh);
  EXPECT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_EQ(prepared.parts.size(), 2u);
}

TEST(UniteByWindingTest, SameGeometryGivesTheSameBytes) {
  // Vertices in exact lexicographic order, triangles sorted: renumbering the input's vertices
  // and faces changes nothing.
  const TriangleMesh tube = SweptTube(1.25, 40, 0.5);
  TriangleMesh shuffled = tube;
  const Eigen::Index n = tube.triangles.rows();
  for (Eigen::Index f = 0; f < n; ++f) shuffled.triangles.row(f) = tube.triangles.row(n - 1 - f);
  const auto a = Unite(tube), b = Unite(shuffled);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(test::Bytes(a->mesh), test::Bytes(b->mesh));
}

}  // namespace
}  // namespace acdplan::acd::internal
