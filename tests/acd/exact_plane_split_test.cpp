#include "acd/internal/exact_plane_split.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "acd/mesh_measures.h"
#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

// A tetrahedron whose corner p is split into p and q one ulp apart in z (q = p + 2^-52 z),
// joined by two needle triangles (p, q, c) and (p, b, q): the shape a sliver of an earlier cut
// or of an input mesh leaves.
TriangleMesh NeedleTetrahedron() {
  const double ulp = std::ldexp(1.0, -52);
  std::vector<Eigen::Vector3d> v = {{1, 0, 1}, {1, 0, 1 + ulp}, {0, 1, 1}, {0, -1, -1}, {0, -1, 3}};
  enum { p, q, c, a, b };
  std::vector<Eigen::Vector3i> f = {{p, c, a}, {p, a, b}, {q, b, c},
                                    {p, b, q}, {p, q, c}, {a, c, b}};
  TriangleMesh mesh = MakeTriangleMesh(v, f);
  if (MeshVolume(mesh) < 0) mesh.triangles.col(1).swap(mesh.triangles.col(2));
  return mesh;
}

bool HasTwoCornersAtOnePosition(const ExactPiece& piece) {
  for (const auto& t : piece.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (piece.rounded[static_cast<size_t>(t[static_cast<size_t>(k)])] ==
          piece.rounded[static_cast<size_t>(t[static_cast<size_t>((k + 1) % 3)])]) {
        return true;
      }
    }
  }
  return false;
}

TEST(ExactPlaneSplitTest, TheNeedleTetrahedronIsAValidSolid) {
  const ExactPiece piece = ToExact(NeedleTetrahedron());
  EXPECT_TRUE(IsClosedSurface(piece.triangles));
  EXPECT_TRUE(RoundsToValidSolid(piece));
  EXPECT_GT(MeshVolume(NeedleTetrahedron()), 0.1);
}

// The plane y = 0.75 crosses the needle's long edges c-p and c-q a quarter of the way from c,
// at z = 1 and z = 1 + 2^-54: distinct exact points that round to one double. Before they were
// joined, the upper half kept the triangle (c, x1, x2) with two corners at one position
// (CheckDecomposition3d: "not closed", as defsphere at tau_rel 0.02 showed).
TEST(ExactPlaneSplitTest, CrossingsThatRoundToOnePositionAreOneVertex) {
  const ExactPiece piece = ToExact(NeedleTetrahedron());
  ExactPiece below, above;
  SplitByPlane(piece, ExactKernel::Plane_3(0, 1, 0, -0.75), &below, &above);
  ASSERT_FALSE(below.triangles.empty());
  ASSERT_FALSE(above.triangles.empty());
  for (const ExactPiece* half : {&below, &above}) {
    EXPECT_TRUE(IsClosedSurface(half->triangles));
    EXPECT_FALSE(HasTwoCornersAtOnePosition(*half));
    EXPECT_TRUE(RoundsToValidSolid(*half));
  }
  const double total = MeshVolume(ToDouble(below)) + MeshVolume(ToDouble(above));
  EXPECT_NEAR(total, MeshVolume(NeedleTetrahedron()), 1e-12);
}

// Single-precision input leaves a wall flat only to ~1e-7 of the size: the plane extending the
// L-block's notch wall x = 1 passes a few 1e-9 from the wall's vertices, which sit on both sides
// of it. Classified exactly, the two vertices at x > 1 put a wedge of volume ~1e-9 into the upper
// half, as a second solid; within kInPlaneTolerance they are on the plane, and the L falls into
// its two blocks, their shared section planar to within the tolerance.
TEST(ExactPlaneSplitTest, VerticesWithinTheInPlaneToleranceAreOnThePlane) {
  TriangleMesh l = test::LBlock();
  for (Eigen::Index i = 0; i < l.vertices.rows(); ++i) {
    if (l.vertices(i, 0) == 1.0) l.vertices(i, 0) += l.vertices(i, 1) > 1.5 ? 3e-9 : -2e-9;
  }
  ExactPiece below, above;
  SplitByPlane(ToExact(l), ExactKernel::Plane_3(1, 0, 0, -1), &below, &above);
  const std::vector<ExactPiece> lower = ConnectedSolids(below), upper = ConnectedSolids(above);
  ASSERT_EQ(lower.size(), 1u);
  ASSERT_EQ(upper.size(), 1u);
  EXPECT_NEAR(MeshVolume(ToDouble(lower[0])), 2.0, 1e-8);
  EXPECT_NEAR(MeshVolume(ToDouble(upper[0])), 1.0, 1e-8);
  for (const ExactPiece* half : {&below, &above}) {
    EXPECT_TRUE(IsClosedSurface(half->triangles));
    EXPECT_TRUE(RoundsToValidSolid(*half));
  }
}

// A cavity whose first vertex is a corner of the box around it (the same vertex): the ray from
// there that the nesting was once decided by leaves the box at once, and the cavity was a solid
// of its own, inside out. Decided exactly, at a vertex off the box, it stays with the box.
TEST(ExactPlaneSplitTest, ACavityTouchingItsShellAtAVertexStaysWithIt) {
  const TriangleMesh box = test::Box({0, 0, 0}, {4, 4, 4});
  const int corner = test::VertexAt(box, {4, 4, 4});
  ASSERT_GE(corner, 0);
  const TriangleMesh solid = test::WithCavityAtCorner(box, corner, {-1, -1, -1}, 1.0);
  ASSERT_NEAR(MeshVolume(solid), 64.0 - 1.0 / 12, 1e-12);
  const std::vector<ExactPiece> solids = ConnectedSolids(ToExact(solid));
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_EQ(solids[0].triangles.size(), 16u);
  EXPECT_NEAR(MeshVolume(ToDouble(solids[0])), 64.0 - 1.0 / 12, 1e-12);
}

// The box [0, 4] x [0, 2] x [0, 2] whose top is two roofs, square [0, 2] x [0, 2] with its apex
// at (1, 1, left) and square [2, 4] x [0, 2] at (3, 1, right): a peak above z = 2, a dimple
// below it.
TriangleMesh BoxWithTwoRoofs(double left, double right) {
  const std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0},    {0, 2, 0},
                                          {0, 0, 2}, {2, 0, 2}, {4, 0, 2},    {4, 2, 2},
                                          {2, 2, 2}, {0, 2, 2}, {1, 1, left}, {3, 1, right}};
  const std::vector<Eigen::Vector3i> f = {
      {0, 2, 1},  {0, 3, 2},  {0, 1, 6},  {0, 6, 5},  {0, 5, 4},  {1, 2, 7},  {1, 7, 6},
      {2, 3, 9},  {2, 9, 8},  {2, 8, 7},  {3, 0, 4},  {3, 4, 9},  {4, 5, 10}, {5, 8, 10},
      {8, 9, 10}, {9, 4, 10}, {5, 6, 11}, {6, 7, 11}, {7, 8, 11}, {8, 5, 11}};
  return MakeTriangleMesh(v, f);
}

// The plane z = 1 is tangent to the left roof's dimple at its bottom (1, 1, 1), which lies inside
// the section (the whole rectangle): the cap would touch the upper half's surface there. The
// split is refused; a plane a hair lower cuts the box cleanly.
TEST(ExactPlaneSplitTest, APlaneTangentToADimpleInsideTheSectionIsRefused) {
  const ExactPiece box = ToExact(BoxWithTwoRoofs(1.0, 2.5));
  ASSERT_TRUE(IsClosedSurface(box.triangles));
  ASSERT_NEAR(MeshVolume(ToDouble(box)), 16.0 - 4.0 / 3.0 + 2.0 / 3.0, 1e-12);
  ExactPiece below, above;
  EXPECT_FALSE(SplitByPlane(box, ExactKernel::Plane_3(0, 0, 1, -1), &below, &above));
  EXPECT_TRUE(below.triangles.empty());
  EXPECT_TRUE(above.triangles.empty());
  ASSERT_TRUE(SplitByPlane(box, ExactKernel::Plane_3(0, 0, 1, -0.99), &below, &above));
  for (const ExactPiece* half : {&below, &above}) {
    EXPECT_TRUE(IsClosedSurface(half->triangles));
    EXPECT_TRUE(RoundsToValidSolid(*half));
  }
  EXPECT_NEAR(MeshVolume(ToDouble(below)), 8 * 0.99, 1e-12);
}

// The box [0, 2]^3 whose top is a groove along y, its bottom edge from (1, 0, 1) to (1, 2, 1).
TriangleMesh GroovedBox() {
  const std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2},
                                          {2, 0, 2}, {2, 2, 2}, {0, 2, 2}, {1, 0, 1}, {1, 2, 1}};
  const std::vector<Eigen::Vector3i> f = {
      {0, 2, 1}, {0, 3, 2}, {1, 2, 6}, {1, 6, 5}, {3, 0, 4}, {3, 4, 7}, {0, 1, 8}, {1, 5, 8},
      {0, 8, 4}, {2, 3, 9}, {3, 7, 9}, {2, 9, 6}, {4, 8, 9}, {4, 9, 7}, {8, 5, 6}, {8, 6, 9}};
  return MakeTriangleMesh(v, f);
}

// The plane z = 1 is tangent to the groove along its bottom edge, whose ends are on the section's
// border (the plane crosses the end walls there) and whose inside crosses the section: refused,
// as for a dimple's vertex.
TEST(ExactPlaneSplitTest, APlaneTangentToAGrooveAlongAnEdgeIsRefused) {
  const ExactPiece box = ToExact(GroovedBox());
  ASSERT_TRUE(IsClosedSurface(box.triangles));
  ASSERT_NEAR(MeshVolume(ToDouble(box)), 6.0, 1e-12);
  ExactPiece below, above;
  EXPECT_FALSE(SplitByPlane(box, ExactKernel::Plane_3(0, 0, 1, -1), &below, &above));
  EXPECT_TRUE(below.triangles.empty() && above.triangles.empty());
  ASSERT_TRUE(SplitByPlane(box, ExactKernel::Plane_3(0, 0, 1, -0.99), &below, &above));
  EXPECT_NEAR(MeshVolume(ToDouble(below)), 4 * 0.99, 1e-12);
}

// The plane z = 3 touches the left roof's peak (1, 1, 3) from outside the solid, away from the
// section (a square around the right roof, whose apex is at z = 4): the cut goes ahead, the peak
// a vertex of the lower half.
TEST(ExactPlaneSplitTest, APlaneTouchingAPeakOutsideTheSectionCuts) {
  const ExactPiece box = ToExact(BoxWithTwoRoofs(3.0, 4.0));
  ExactPiece below, above;
  ASSERT_TRUE(SplitByPlane(box, ExactKernel::Plane_3(0, 0, 1, -3), &below, &above));
  for (const ExactPiece* half : {&below, &above}) {
    EXPECT_TRUE(IsClosedSurface(half->triangles));
    EXPECT_TRUE(RoundsToValidSolid(*half));
  }
  EXPECT_NEAR(MeshVolume(ToDouble(above)), 1.0 / 3.0, 1e-12);  // the top of a pyramid of 8 / 3
}

// A piece with a triangle whose corners round onto one position is not a valid output.
TEST(ExactPlaneSplitTest, RoundsToValidSolidRejectsTwoCornersAtOnePosition) {
  ExactPiece piece = ToExact(NeedleTetrahedron());
  piece.rounded[1] = piece.rounded[0];  // q rounded onto p
  EXPECT_FALSE(RoundsToValidSolid(piece));
}

// Given the piece it was cut from, RoundsToValidSolid tests only pairs with a fresh face: here the
// unit box whose top is replaced by a tent with its apex below the bottom, so the fresh tent faces
// cross the box's old bottom faces. Both ways must reject it; the box itself passes both ways.
TEST(ExactPlaneSplitTest, RoundsToValidSolidFindsFreshFacesCrossingOldOnes) {
  std::vector<Eigen::Vector3d> v;
  for (int k = 0; k < 8; ++k) v.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  std::vector<Eigen::Vector3i> sides = {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}, {1, 3, 7},
                                        {1, 7, 5}, {3, 2, 6}, {3, 6, 7}, {2, 0, 4}, {2, 4, 6}};
  std::vector<Eigen::Vector3i> box_faces = sides;
  box_faces.emplace_back(4, 5, 7);
  box_faces.emplace_back(4, 7, 6);
  const ExactPiece box = ToExact(MakeTriangleMesh(v, box_faces));
  ASSERT_GT(MeshVolume(ToDouble(box)), 0.0);
  v.emplace_back(0.5, 0.5, -0.5);  // 8: the tent's apex, below the bottom z = 0
  std::vector<Eigen::Vector3i> tent_faces = sides;
  for (const auto& [a, b] : {std::pair{4, 5}, {5, 7}, {7, 6}, {6, 4}})
    tent_faces.emplace_back(a, b, 8);
  const ExactPiece tent = ToExact(MakeTriangleMesh(v, tent_faces));
  ASSERT_TRUE(IsClosedSurface(tent.triangles));
  EXPECT_TRUE(RoundsToValidSolid(box));
  const RoundedFaceSet faces_of_box(box);
  EXPECT_TRUE(faces_of_box.Contains(tent, tent.triangles.front()));  // a side, in its order
  EXPECT_TRUE(faces_of_box.Contains(
      tent, {tent.triangles[0][1], tent.triangles[0][2], tent.triangles[0][0]}));  // rotated
  EXPECT_FALSE(faces_of_box.Contains(tent, tent.triangles.back()));                // a tent face
  EXPECT_TRUE(RoundsToValidSolid(box, &faces_of_box));
  EXPECT_FALSE(RoundsToValidSolid(tent));
  EXPECT_FALSE(RoundsToValidSolid(tent, &faces_of_box));
}

// Shells are joined across edges with exactly two faces; the genus sums (2 - V + E - F) / 2 over
// them, each shell counting its own vertices and edges.
TEST(ExactPlaneSplitTest, TopologyCountsShellsAndTheirGenus) {
  auto topology = [](const TriangleMesh& mesh) {
    const ShellTopology t = Topology(ToExact(mesh).triangles);
    return std::make_pair(t.shells, t.genus);
  };
  const TriangleMesh box = test::Box({0, 0, 0}, {1, 1, 1});
  const TriangleMesh torus = test::Torus(2, 0.5, 12, 8);
  EXPECT_EQ(topology(box), std::make_pair(1, 0));
  EXPECT_EQ(topology(torus), std::make_pair(1, 1));
  EXPECT_EQ(topology(test::Concatenate(box, test::Box({3, 0, 0}, {4, 1, 1}))),
            std::make_pair(2, 0));
  EXPECT_EQ(topology(test::Concatenate(torus, test::Concatenate(torus, box))),
            std::make_pair(3, 2));
  // Two tetrahedra sharing the edge 0-1: its four faces join neither, so two shells of genus 0,
  // each with the shared edge and its ends.
  const std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {0, 0, 1},  {1, 0, 0},
                                          {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  const std::vector<Eigen::Vector3i> f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                                          {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}};
  EXPECT_EQ(topology(MakeTriangleMesh(v, f)), std::make_pair(2, 0));
  // Closed: each edge has two faces running along it in opposite directions.
  EXPECT_TRUE(Topology(ToExact(box).triangles).closed);
  EXPECT_TRUE(Topology(ToExact(torus).triangles).closed);
  EXPECT_FALSE(Topology(ToExact(MakeTriangleMesh(v, f)).triangles).closed);  // four on 0-1
  std::vector<std::array<int, 3>> open = ToExact(box).triangles;
  open.pop_back();
  EXPECT_FALSE(Topology(open).closed);
  EXPECT_FALSE(IsClosedSurface(open));
  std::vector<std::array<int, 3>> flipped = ToExact(box).triangles;
  std::swap(flipped[0][1], flipped[0][2]);
  EXPECT_FALSE(Topology(flipped).closed);
  EXPECT_FALSE(IsClosedSurface(flipped));
  EXPECT_TRUE(IsClosedSurface(ToExact(box).triangles));
}

}  // namespace
}  // namespace acdplan::acd::internal
