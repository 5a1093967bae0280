#include "acd/prepare_mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "acd/mesh_measures.h"
#include "base/input_error.h"
#include "envs/mesh_loader.h"
#include "solid_test_meshes.h"
#include "tests/asan_build.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

using ::testing::HasSubstr;

PrepareMeshOptions Repair() {
  PrepareMeshOptions options;
  options.repair = true;
  return options;
}

// Cube(side) moved by `offset`.
TriangleMesh CubeAt(double side, const Eigen::Vector3d& offset) {
  TriangleMesh cube = Cube(side);
  cube.vertices.rowwise() += offset.transpose();
  return cube;
}

TriangleMesh WithoutTriangles(const TriangleMesh& mesh, const std::vector<int>& drop) {
  TriangleMesh out = mesh;
  out.triangles.resize(0, 3);
  std::vector<Eigen::Vector3i> kept;
  for (int f = 0; f < mesh.triangles.rows(); ++f) {
    if (std::find(drop.begin(), drop.end(), f) == drop.end()) {
      kept.push_back(mesh.triangles.row(f).transpose());
    }
  }
  out.triangles.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i)
    out.triangles.row(static_cast<Eigen::Index>(i)) = kept[i];
  return out;
}

TriangleMesh AppendTriangle(TriangleMesh mesh, const Eigen::Vector3i& t) {
  mesh.triangles.conservativeResize(mesh.triangles.rows() + 1, 3);
  mesh.triangles.row(mesh.triangles.rows() - 1) = t;
  return mesh;
}

TriangleMesh AppendVertex(TriangleMesh mesh, const Eigen::Vector3d& p) {
  mesh.vertices.conservativeResize(mesh.vertices.rows() + 1, 3);
  mesh.vertices.row(mesh.vertices.rows() - 1) = p;
  return mesh;
}

// Every edge of `mesh` is run once in each direction: closed and consistently oriented.
bool ClosedAndConsistent(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> runs;
  for (int f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) ++runs[{mesh.triangles(f, k), mesh.triangles(f, (k + 1) % 3)}];
  }
  for (const auto& [edge, count] : runs) {
    if (count != 1 || runs.count({edge.second, edge.first}) == 0) return false;
  }
  return true;
}

bool HasNote(const PreparedMesh& prepared, const std::string& text) {
  for (const std::string& note : prepared.notes) {
    if (note.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string ErrorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(PrepareMeshTest, CubeIsOneSolidPartUnchanged) {
  const TriangleMesh cube = Cube(2);
  const PreparedMesh prepared = PrepareMesh(cube);
  EXPECT_TRUE(prepared.solid());
  EXPECT_TRUE(prepared.defects.none());
  EXPECT_EQ(prepared.defects.first, "");
  EXPECT_EQ(prepared.mesh.vertices, cube.vertices);
  EXPECT_EQ(prepared.mesh.triangles, cube.triangles);
  ASSERT_EQ(prepared.parts.size(), 1u);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[0]), 8.0);
  EXPECT_EQ(prepared.closed_parts, std::vector<bool>{true});
  EXPECT_TRUE(HasNote(prepared, "found 1 solid part"));
  EXPECT_FALSE(HasNote(prepared, "merged"));
  EXPECT_FALSE(HasNote(prepared, "reoriented"));
  EXPECT_NO_THROW(RequireSolid(prepared, "cube.obj"));
}

TEST(PrepareMeshTest, MergesVerticesSplitAtSeams) {
  // Every triangle with its own three vertices, as an OBJ file with per-face normals gives.
  const TriangleMesh cube = Cube(2);
  TriangleMesh split;
  split.vertices.resize(36, 3);
  split.triangles.resize(12, 3);
  for (int f = 0; f < 12; ++f) {
    for (int k = 0; k < 3; ++k) {
      split.vertices.row(3 * f + k) = cube.vertices.row(cube.triangles(f, k));
      split.triangles(f, k) = 3 * f + k;
    }
  }
  const PreparedMesh prepared = PrepareMesh(split);
  EXPECT_EQ(prepared.mesh.vertices.rows(), 8);
  EXPECT_EQ(prepared.mesh.triangles.rows(), 12);
  EXPECT_TRUE(prepared.solid());
  EXPECT_TRUE(HasNote(prepared, "merged 28 duplicate vertices"));
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.mesh), 8.0);
}

TEST(PrepareMeshTest, MergesMinusZeroWithZero) {
  TriangleMesh cube = Cube(2);
  cube = AppendVertex(cube, Eigen::Vector3d(0, 0, 0));
  cube = AppendVertex(cube, Eigen::Vector3d(-0.0, 0, 0));
  const PreparedMesh prepared = PrepareMesh(cube);
  EXPECT_TRUE(HasNote(prepared, "merged 1 duplicate vertex"));
  EXPECT_TRUE(HasNote(prepared, "dropped 1 unreferenced vertex"));
  EXPECT_EQ(prepared.mesh.vertices.rows(), 8);
}

TEST(PrepareMeshTest, ReorientsAFlippedFace) {
  TriangleMesh cube = Cube(2);
  std::swap(cube.triangles(5, 1), cube.triangles(5, 2));
  const PreparedMesh prepared = PrepareMesh(cube);
  EXPECT_TRUE(prepared.solid());
  EXPECT_TRUE(HasNote(prepared, "reoriented 1 face"));
  EXPECT_TRUE(ClosedAndConsistent(prepared.mesh));
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.mesh), 8.0);
}

TEST(PrepareMeshTest, TurnsAnInwardCubeOutward) {
  TriangleMesh cube = Cube(2);
  cube.triangles.col(1).swap(cube.triangles.col(2));
  ASSERT_LT(MeshVolume(cube), 0);
  const PreparedMesh prepared = PrepareMesh(cube);
  EXPECT_TRUE(prepared.solid());
  EXPECT_TRUE(HasNote(prepared, "reoriented 12 faces"));
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.mesh), 8.0);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[0]), 8.0);
}

TEST(PrepareMeshTest, OrientsAFarThinSlabOutward) {
  // Volume 1e-6 at 1e6 from the origin: the tetrahedra about a vertex keep the sign exact.
  TriangleMesh slab = Cube(1);
  slab.vertices.col(2) *= 1e-6;
  slab.vertices.rowwise() += Eigen::RowVector3d(1e6, -1e6, 1e6);
  slab.triangles.col(1).swap(slab.triangles.col(2));
  const PreparedMesh prepared = PrepareMesh(slab);
  EXPECT_TRUE(prepared.solid());
  EXPECT_GT(MeshVolume(prepared.mesh), 0);
}

// Found through fuzz/fuzz_decompose3d: a tetrahedron of four lattice points that are coplanar
// until rounded to doubles (volume about 2e-33; the floating-point sum cannot tell its sign, the
// exact one decides). The exact sum read its differences through dangling references (GMP's
// expression templates; ASan does not see into GMP, valgrind did), so the prepared orientation
// changed from run to run. Checked in both orientations, each several times.
TEST(PrepareMeshTest, OrientsASliverByItsExactVolumeSign) {
  const TriangleMesh outward = test::LatticeSliver();
  TriangleMesh inward = outward;
  inward.triangles.col(1).swap(inward.triangles.col(2));
  for (int run = 0; run < 8; ++run) {
    const PreparedMesh kept = PrepareMesh(outward);
    ASSERT_TRUE(kept.solid());
    EXPECT_EQ(kept.mesh.triangles, outward.triangles) << "run " << run;
    const PreparedMesh turned = PrepareMesh(inward);
    ASSERT_TRUE(turned.solid());
    EXPECT_EQ(turned.mesh.triangles, outward.triangles) << "run " << run;
  }
}

TEST(PrepareMeshTest, DropsDegenerateAndDuplicateFaces) {
  TriangleMesh cube = AppendVertex(Cube(2), Eigen::Vector3d(0, -1, -1));  // Midpoint of 0-1.
  cube = AppendTriangle(cube, Eigen::Vector3i(0, 8, 1));                  // Collinear.
  cube = AppendTriangle(cube, Eigen::Vector3i(2, 2, 3));                  // Repeated index.
  cube = AppendTriangle(cube, Eigen::Vector3i(3, 2, 1));                  // Face 1 reversed.
  const PreparedMesh prepared = PrepareMesh(cube);
  EXPECT_TRUE(prepared.solid());
  EXPECT_EQ(prepared.mesh.triangles.rows(), 12);
  EXPECT_EQ(prepared.mesh.vertices.rows(), 8);
  EXPECT_TRUE(HasNote(prepared, "dropped 2 degenerate faces (first: face 12)"));
  EXPECT_TRUE(HasNote(prepared, "dropped 1 duplicate face (first: face 14)"));
  EXPECT_TRUE(HasNote(prepared, "dropped 1 unreferenced vertex"));
}

TEST(PrepareMeshTest, RepairLeavesAFaceGivenBothWaysAloneWhenCleaningMadeASolid) {
  const TriangleMesh cube = AppendTriangle(Cube(2), Eigen::Vector3i(3, 2, 1));  // Face 1 reversed.
  const PreparedMesh repaired = PrepareMesh(cube, Repair());
  EXPECT_TRUE(repaired.solid());
  EXPECT_EQ(repaired.mesh.triangles.rows(), 12);
  EXPECT_DOUBLE_EQ(MeshVolume(repaired.mesh), 8.0);
  EXPECT_FALSE(HasNote(repaired, "repair:"));
}

// Two unit cubes that share the face x = 1, each a closed shell: the face comes once each way,
// as where a CAD assembly's blocks touch. Cleaning keeps one copy, whose edges then have three
// faces; repair drops both copies (no volume), which leaves the union, a 2 x 1 x 1 box.
TEST(PrepareMeshTest, RepairDropsAFaceTwoShellsShareBackToBack) {
  const TriangleMesh left = CubeAt(1, {0.5, 0.5, 0.5});
  TriangleMesh right = left;  // Mirrored in x = 1 (the shared face's own triangles), outward.
  right.vertices.col(0) = (2.0 - left.vertices.col(0).array()).matrix();
  right.triangles.col(1).swap(right.triangles.col(2));
  const TriangleMesh pair = test::Concatenate(left, right);
  const PreparedMesh diagnosed = PrepareMesh(pair);
  EXPECT_FALSE(diagnosed.solid());
  EXPECT_EQ(diagnosed.defects.non_manifold_edges, 4);  // The shared square's sides.
  EXPECT_TRUE(HasNote(diagnosed, "dropped 2 duplicate faces"));

  const PreparedMesh repaired = PrepareMesh(pair, Repair());
  ASSERT_TRUE(repaired.solid()) << repaired.defects.first;
  ASSERT_EQ(repaired.parts.size(), 1u);
  EXPECT_EQ(repaired.mesh.triangles.rows(), 20);
  EXPECT_DOUBLE_EQ(MeshVolume(repaired.parts[0]), 2.0);
  EXPECT_TRUE(HasNote(repaired,
                      "repair: dropped 2 faces given as often one way as the other (first: face"));
}

// A two-sided sheet (a triangle given both ways) inside a cube, hinged on one of its edges: a
// surface, with a non-manifold edge, until repair drops the sheet. A sheet on its own has nothing
// else to keep: repair leaves it as cleaning does.
TEST(PrepareMeshTest, RepairDropsATwoSidedSheetInsideASolidButNotASheetAlone) {
  TriangleMesh cube = AppendVertex(Cube(2), Eigen::Vector3d(0, 0, 0));
  cube = AppendTriangle(cube, Eigen::Vector3i(3, 7, 8));
  cube = AppendTriangle(cube, Eigen::Vector3i(7, 3, 8));
  const PreparedMesh diagnosed = PrepareMesh(cube);
  EXPECT_FALSE(diagnosed.solid());
  EXPECT_EQ(diagnosed.mesh.triangles.rows(), 13);  // One copy of the sheet kept.
  EXPECT_EQ(diagnosed.defects.non_manifold_edges, 1);
  const PreparedMesh repaired = PrepareMesh(cube, Repair());
  ASSERT_TRUE(repaired.solid()) << repaired.defects.first;
  EXPECT_EQ(repaired.mesh.triangles.rows(), 12);
  EXPECT_DOUBLE_EQ(MeshVolume(repaired.mesh), 8.0);
  EXPECT_TRUE(HasNote(repaired, "repair: dropped 1 face given as often one way as the other"));

  const std::vector<Eigen::Vector3d> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const TriangleMesh sheet = MakeTriangleMesh(v, {{0, 1, 2}, {0, 2, 1}});
  const PreparedMesh alone = PrepareMesh(sheet, Repair());
  EXPECT_FALSE(alone.solid());
  EXPECT_EQ(alone.parts.size(), 1u);
  EXPECT_FALSE(HasNote(alone, "given as often"));
}

TEST(PrepareMeshTest, RejectsAMeshWithoutAreaAndInvalidMeshes) {
  TriangleMesh flat;
  flat.vertices.resize(3, 3);
  flat.vertices << 0, 0, 0, 1, 1, 1, 2, 2, 2;
  flat.triangles.resize(1, 3);
  flat.triangles << 0, 1, 2;
  EXPECT_EQ(ErrorOf([&] { PrepareMesh(flat, {}, "line.obj"); }),
            "line.obj: mesh has no face of positive area (all 1 face are degenerate)");
  TriangleMesh empty;
  EXPECT_EQ(ErrorOf([&] { PrepareMesh(empty, {}, "empty.obj"); }),
            "empty.obj: mesh has no triangles");
  TriangleMesh bad = Cube(1);
  bad.triangles(3, 1) = 8;
  EXPECT_THAT(ErrorOf([&] { PrepareMesh(bad, {}, "bad.obj"); }),
              HasSubstr("bad.obj: triangle 3: index 8 out of range [0, 8)"));
}

TEST(PrepareMeshTest, OpenBoxHasBoundaryEdgesAndIsNotSolid) {
  const TriangleMesh box = WithoutTriangles(Cube(2), {2, 3});  // No top (z+).
  const PreparedMesh prepared = PrepareMesh(box);
  EXPECT_FALSE(prepared.solid());
  EXPECT_EQ(prepared.defects.boundary_edges, 4);
  EXPECT_EQ(prepared.defects.non_manifold_edges, 0);
  EXPECT_EQ(prepared.defects.self_intersections, 0);
  EXPECT_EQ(prepared.defects.first,
            "edge 4-5 at (0, -1, 1) has 1 face (a solid's edges have exactly 2)");
  ASSERT_EQ(prepared.parts.size(), 1u);  // One surface patch.
  EXPECT_EQ(prepared.parts[0].triangles.rows(), 10);
  EXPECT_EQ(prepared.closed_parts, std::vector<bool>{false});
  EXPECT_EQ(ErrorOf([&] { RequireSolid(prepared, "box.obj"); }),
            "box.obj: not a solid: edge 4-5 at (0, -1, 1) has 1 face (a solid's edges have "
            "exactly 2) (use --repair to close holes and remove self-intersections, or "
            "--surface)");
}

TEST(PrepareMeshTest, RepairClosesTheOpenBox) {
  TriangleMesh box = WithoutTriangles(Cube(2), {2, 3});
  box.triangles.col(1).swap(box.triangles.col(2));  // Inward, too.
  const PreparedMesh prepared = PrepareMesh(box, Repair());
  EXPECT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_TRUE(HasNote(prepared, "repair: filled 1 hole with 2 triangles"));
  ASSERT_EQ(prepared.parts.size(), 1u);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[0]), 8.0);
  EXPECT_TRUE(ClosedAndConsistent(prepared.mesh));
}

TEST(PrepareMeshTest, RepairClosesAPyramidWithAnOctagonalHole) {
  // A cone over a regular octagon, base open: one hole of 8 edges.
  std::vector<Eigen::Vector3d> v{{0, 0, 1}};
  std::vector<Eigen::Vector3i> t;
  for (int i = 0; i < 8; ++i) {
    v.emplace_back(std::cos(i * M_PI / 4), std::sin(i * M_PI / 4), 0);
    t.emplace_back(0, 1 + i, 1 + (i + 1) % 8);
  }
  const PreparedMesh open = PrepareMesh(MakeTriangleMesh(v, t));
  EXPECT_EQ(open.defects.boundary_edges, 8);
  const PreparedMesh prepared = PrepareMesh(MakeTriangleMesh(v, t), Repair());
  ASSERT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_NEAR(MeshVolume(prepared.mesh), 2 * std::sqrt(2.0) / 3, 1e-12);  // Octagon area 2 sqrt 2.
}

TEST(PrepareMeshTest, RepairClosesAnLShapedHoleInItsPlane) {
  // An L-shaped prism, its top open: the hole is planar and not convex, so its filling must
  // keep to the L (a triangle across the notch would add volume).
  const std::vector<Eigen::Vector2d> l{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  const int n = static_cast<int>(l.size());
  std::vector<Eigen::Vector3d> v;
  for (const double z : {0.0, 2.0}) {
    for (const Eigen::Vector2d& p : l) v.emplace_back(p.x(), p.y(), z);
  }
  std::vector<Eigen::Vector3i> t{{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 5, 4}};  // The bottom.
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    t.emplace_back(i, j, j + n);
    t.emplace_back(i, j + n, i + n);
  }
  const PreparedMesh prepared = PrepareMesh(MakeTriangleMesh(v, t), Repair());
  ASSERT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_TRUE(HasNote(prepared, "repair: filled 1 hole with 4 triangles"));
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.mesh), 2.0 * 7.0);  // The L's area is 7.
}

// Found by fuzz/fuzz_decompose3d (fuzz/corpus/decompose3d/regression-hole-projection-not-simple
// .bin): repairing this patchwork of a cube's faces and stray triangles sent a boundary loop
// into CGAL's planar hole filling, whose projection along a rounded average normal let an
// inconsistent constrained triangulation dereference a null pointer (undefined behaviour; the
// sanitizer suite reports it). Holes are now triangulated in an exact projection, or by CGAL's
// 3D search when that projection is not simple.
TEST(PrepareMeshTest, RepairOfAHoleWhoseProjectionIsDegenerateIsDefined) {
  const std::vector<Eigen::Vector3d> v{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0},
                                       {0, 0, 4}, {4, 0, 4}, {4, 4, 4}, {0, 4, 31.5},
                                       {4, 2, 2}, {2, 6, 2}, {2, 6, 6}, {2, 2, -14.75},
                                       {2, 2, 2}, {6, 6, 2}, {6, 6, 6}, {6, 2, 6}};
  const std::vector<Eigen::Vector3i> t{{8, 0, 2},  {1, 0, 3}, {2, 4, 5}, {6, 4, 6},   {7, 0, 1},
                                       {5, 12, 0}, {5, 4, 1}, {2, 6, 1}, {12, 11, 12}};
  PreparedMesh prepared;
  ASSERT_NO_THROW(prepared = PrepareMesh(MakeTriangleMesh(v, t), Repair()));
  EXPECT_FALSE(prepared.parts.empty());
  EXPECT_FALSE(prepared.solid());  // Repair closes what it can; the rest stays diagnosed.
}

TEST(PrepareMeshTest, ThreeFacesOnOneEdgeAreNonManifold) {
  // A fin on the cube's edge 3-7.
  TriangleMesh cube = AppendVertex(Cube(2), Eigen::Vector3d(3, 3, 0));
  cube = AppendTriangle(cube, Eigen::Vector3i(3, 7, 8));
  const PreparedMesh prepared = PrepareMesh(cube);
  EXPECT_FALSE(prepared.solid());
  EXPECT_EQ(prepared.defects.non_manifold_edges, 1);
  EXPECT_EQ(prepared.defects.boundary_edges, 2);
  // Repair cannot mend it: the defects stay.
  const PreparedMesh repaired = PrepareMesh(cube, Repair());
  EXPECT_FALSE(repaired.solid());
  EXPECT_GE(repaired.defects.non_manifold_edges, 1);
  EXPECT_TRUE(HasNote(repaired, "repair: still not a solid"));
}

TEST(PrepareMeshTest, CubesSharingAnEdgeNameTheNonManifoldEdge) {
  const TriangleMesh pair =
      test::Concatenate(CubeAt(1, {0.5, 0.5, 0.5}), CubeAt(1, {1.5, 1.5, 0.5}));
  const PreparedMesh prepared = PrepareMesh(pair);
  EXPECT_FALSE(prepared.solid());
  EXPECT_EQ(prepared.defects.boundary_edges, 0);
  EXPECT_EQ(prepared.defects.non_manifold_edges, 1);
  EXPECT_EQ(prepared.defects.self_intersections, 0);
  EXPECT_EQ(prepared.defects.first,
            "edge 3-7 at (1, 1, 0.5) has 4 faces (a solid's edges have exactly 2)");
}

TEST(PrepareMeshTest, InterpenetratingCubesSelfIntersectAndRepairUnitesThem) {
  const TriangleMesh pair = test::Concatenate(Cube(2), CubeAt(2, {1, 1, 1}));
  const PreparedMesh prepared = PrepareMesh(pair);
  EXPECT_FALSE(prepared.solid());
  EXPECT_EQ(prepared.defects.boundary_edges, 0);
  EXPECT_GT(prepared.defects.self_intersections, 0);
  EXPECT_THAT(prepared.defects.first, HasSubstr(" intersect at ("));
  EXPECT_THAT(prepared.defects.first, HasSubstr("(a solid's surface does not cross itself)"));
  EXPECT_EQ(prepared.parts.size(), 2u);  // The two surfaces, as patches, each closed.
  EXPECT_EQ(prepared.closed_parts, std::vector<bool>({true, true}));

  const PreparedMesh repaired = PrepareMesh(pair, Repair());
  ASSERT_TRUE(repaired.solid()) << repaired.defects.first;
  EXPECT_TRUE(HasNote(repaired, "repair: united 2 crossing closed shells into 1 solid"));
  ASSERT_EQ(repaired.parts.size(), 1u);
  EXPECT_NEAR(MeshVolume(repaired.parts[0]), 8 + 8 - 1, 1e-12);
  EXPECT_TRUE(ClosedAndConsistent(repaired.mesh));
}

TEST(PrepareMeshTest, TwoDisjointCubesAreTwoSolidParts) {
  const TriangleMesh pair = test::Concatenate(Cube(2), CubeAt(1, {5, 0, 0}));
  const PreparedMesh prepared = PrepareMesh(pair);
  EXPECT_TRUE(prepared.solid());
  ASSERT_EQ(prepared.parts.size(), 2u);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[0]), 8.0);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[1]), 1.0);
  EXPECT_TRUE(HasNote(prepared, "found 2 solid parts"));
}

TEST(PrepareMeshTest, CubesTouchingAtAVertexAreTwoSolidParts) {
  const TriangleMesh pair = test::Concatenate(Cube(2), CubeAt(2, {2, 2, 2}));
  const PreparedMesh prepared = PrepareMesh(pair);
  EXPECT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_EQ(prepared.mesh.vertices.rows(), 15);  // The shared corner merged.
  ASSERT_EQ(prepared.parts.size(), 2u);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[1]), 8.0);
}

TEST(PrepareMeshTest, BoxWithACavityIsOnePartOfTwoShells) {
  // The cavity as given faces outward, like the box: preparation turns it inward.
  for (const bool cavity_first : {false, true}) {
    const TriangleMesh outer = Cube(4), inner = CubeAt(2, {0.5, 0, 0});
    const TriangleMesh box =
        cavity_first ? test::Concatenate(inner, outer) : test::Concatenate(outer, inner);
    const PreparedMesh prepared = PrepareMesh(box);
    EXPECT_TRUE(prepared.solid());
    ASSERT_EQ(prepared.parts.size(), 1u);
    EXPECT_EQ(prepared.parts[0].triangles.rows(), 24);
    EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[0]), 64.0 - 8.0);
    EXPECT_DOUBLE_EQ(MeshVolume(prepared.mesh), 64.0 - 8.0);
    EXPECT_TRUE(HasNote(prepared, "found 1 solid part with 1 cavity"));
    EXPECT_TRUE(ClosedAndConsistent(prepared.parts[0]));
  }
}

// The most fans (faces around a vertex joined across their edges through it) at one vertex.
int MostFansAtAVertex(const TriangleMesh& mesh) {
  int most = 0;
  for (int v = 0; v < mesh.vertices.rows(); ++v) {
    std::vector<std::set<int>> fans;  // each fan's vertices other than v
    for (int f = 0; f < mesh.triangles.rows(); ++f) {
      std::set<int> others;
      for (int k = 0; k < 3; ++k) {
        if (mesh.triangles(f, k) != v) others.insert(mesh.triangles(f, k));
      }
      if (others.size() != 2) continue;
      // Joins every fan it shares an edge through v with.
      for (auto it = fans.begin(); it != fans.end();) {
        if (std::any_of(it->begin(), it->end(), [&](int w) { return others.count(w) > 0; })) {
          others.insert(it->begin(), it->end());
          it = fans.erase(it);
        } else {
          ++it;
        }
      }
      fans.push_back(others);
    }
    most = std::max(most, static_cast<int>(fans.size()));
  }
  return most;
}

// A valid solid whose surface meets itself at a corner: the cavity's copy of the corner moves a
// hair into the cavity, the box keeps its corner, and each vertex has one fan. The same whichever
// shell comes first.
TEST(PrepareMeshTest, ACavityTouchingTheOuterShellAtAVertexIsMovedOffIt) {
  const TriangleMesh box = test::Box({0, 0, 0}, {4, 4, 4});
  const TriangleMesh touching =
      test::WithCavityAtCorner(box, test::VertexAt(box, {4, 4, 4}), {-1, -1, -1}, 1.0);
  TriangleMesh cavity_first = touching;
  const Eigen::Index n = touching.triangles.rows();
  cavity_first.triangles << touching.triangles.bottomRows(4), touching.triangles.topRows(n - 4);
  for (const TriangleMesh& solid : {touching, cavity_first}) {
    ASSERT_EQ(MostFansAtAVertex(solid), 2);
    const PreparedMesh prepared = PrepareMesh(solid);
    ASSERT_TRUE(prepared.solid()) << prepared.defects.first;
    ASSERT_EQ(prepared.parts.size(), 1u);
    EXPECT_TRUE(
        HasNote(prepared, "separated the fans of 1 pinch vertex where a part touches itself"));
    EXPECT_TRUE(HasNote(prepared, "found 1 solid part with 1 cavity"));
    EXPECT_EQ(prepared.mesh.vertices.rows(), 12);
    EXPECT_EQ(MostFansAtAVertex(prepared.mesh), 1);
    EXPECT_GE(test::VertexAt(prepared.mesh, {4, 4, 4}), 0);
    // The cavity's apex moved 1e-3 of the shortest edge there (sqrt(1.5)) along the diagonal,
    // toward its opposite face (area sqrt(3) / 8): the cavity (volume 1/12) shrank by a third of
    // their product.
    const double shrink = 1e-3 * std::sqrt(1.5) * (std::sqrt(3.0) / 8) / 3;
    EXPECT_NEAR(MeshVolume(prepared.mesh), 64.0 - 1.0 / 12 + shrink, 1e-12);
  }
}

TEST(PrepareMeshTest, AnIslandInACavityIsASecondPart) {
  const TriangleMesh shells =
      test::Concatenate(test::Concatenate(Cube(8), CubeAt(4, {0, 0, 0})), CubeAt(2, {0, 0, 0}));
  const PreparedMesh prepared = PrepareMesh(shells);
  EXPECT_TRUE(prepared.solid());
  ASSERT_EQ(prepared.parts.size(), 2u);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[0]), 512.0 - 64.0);
  EXPECT_DOUBLE_EQ(MeshVolume(prepared.parts[1]), 8.0);
}

TEST(PrepareMeshTest, ResultDoesNotDependOnTriangleOrder) {
  const TriangleMesh box = test::Concatenate(CubeAt(4, {1, 2, 3}), CubeAt(2, {1.5, 2, 3}));
  TriangleMesh reversed = box;
  reversed.triangles = box.triangles.colwise().reverse();
  const PreparedMesh a = PrepareMesh(box), b = PrepareMesh(reversed);
  ASSERT_TRUE(a.solid());
  ASSERT_TRUE(b.solid());
  EXPECT_EQ(a.parts.size(), b.parts.size());
  EXPECT_DOUBLE_EQ(MeshVolume(a.mesh), MeshVolume(b.mesh));
}

TEST(PrepareMeshTest, AMoebiusBandIsAnOpenPatchAndRepairDoesNotCrash) {
  // 12 quads around a circle with a half twist: one boundary loop of 24 edges, not orientable.
  const int n = 12;
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> t;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    const Eigen::Vector3d centre(3 * std::cos(a), 3 * std::sin(a), 0);
    const Eigen::Vector3d across = std::cos(a / 2) * Eigen::Vector3d(std::cos(a), std::sin(a), 0) +
                                   std::sin(a / 2) * Eigen::Vector3d::UnitZ();
    v.push_back(centre + across);
    v.push_back(centre - across);
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    // The last quad meets the first with its sides swapped: the half twist.
    const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    t.emplace_back(a, b, d);
    t.emplace_back(a, d, c);
  }
  const TriangleMesh band = MakeTriangleMesh(v, t);
  const PreparedMesh prepared = PrepareMesh(band);
  EXPECT_FALSE(prepared.solid());
  EXPECT_EQ(prepared.defects.boundary_edges, 2 * n);
  ASSERT_EQ(prepared.parts.size(), 1u);
  EXPECT_EQ(prepared.closed_parts, std::vector<bool>{false});
  PreparedMesh repaired;
  ASSERT_NO_THROW(repaired = PrepareMesh(band, Repair()));
  EXPECT_FALSE(repaired.parts.empty());
}

TEST(PrepareMeshTest, RepairReplacesAShellThatCrossesItselfByItsSolid) {
  // teddy.obj is closed and manifold, but one shell crosses itself in 6 pairs of faces: repair
  // replaces it by the solid it winds around (UniteByWinding), where the overlap counts once.
  const TriangleMesh teddy = envs::ReadMesh(acdplan::test::DataDir() + "/meshes/vhacd/teddy.obj");
  const PreparedMesh as_read = PrepareMesh(teddy, {}, "teddy.obj");
  EXPECT_FALSE(as_read.solid());
  EXPECT_EQ(as_read.defects.self_intersections, 6);
  EXPECT_THAT(ErrorOf([&] { RequireSolid(as_read, "teddy.obj"); }),
              HasSubstr("teddy.obj: not a solid: faces "));
  const PreparedMesh prepared = PrepareMesh(teddy, Repair(), "teddy.obj");
  EXPECT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_EQ(prepared.closed_parts, std::vector<bool>{true});
  EXPECT_TRUE(HasNote(prepared, "repair: replaced 1 shell that crosses itself (first: faces "));
  const double volume = MeshVolume(prepared.mesh);
  EXPECT_GT(volume, 0.99 * MeshVolume(as_read.mesh));
  EXPECT_LT(volume, MeshVolume(as_read.mesh));
}

TEST(ReferenceRadiusTest, CubeOfSideTwoHasRadiusSqrtThree) {
  EXPECT_NEAR(ReferenceRadius(Cube(2)), std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(ReferenceRadius(CubeAt(2, {100, -50, 7})), std::sqrt(3.0), 1e-12);
}

// Every mesh of the corpus: preparation never throws; with repair, every part of a solid
// result is closed, consistently oriented and bounds a positive volume. A sanitizer build
// takes every third mesh.
TEST(PrepareMeshCorpusTest, EveryVhacdMeshPreparesAndRepairsIntoPositiveParts) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(acdplan::test::DataDir() + "/meshes/vhacd")) {
    if (entry.path().extension() == ".obj") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), 31u);
#if ACDPLAN_ASAN_BUILD
  const size_t stride = 3;
#else
  const size_t stride = 1;
#endif
  int solids = 0;
  for (size_t i = 0; i < files.size(); i += stride) {
    const std::string name = files[i].filename().string();
    const TriangleMesh mesh = envs::ReadMesh(files[i].string());
    PreparedMesh plain, repaired;
    ASSERT_NO_THROW(plain = PrepareMesh(mesh, {}, name)) << name;
    EXPECT_FALSE(plain.parts.empty()) << name;
    EXPECT_EQ(plain.defects.none(), plain.defects.first.empty()) << name;
    ASSERT_NO_THROW(repaired = PrepareMesh(mesh, Repair(), name)) << name;
    if (plain.solid()) {
      EXPECT_TRUE(repaired.solid()) << name;  // Repair leaves a solid alone.
    }
    if (!repaired.solid()) continue;
    ++solids;
    for (size_t p = 0; p < repaired.parts.size(); ++p) {
      EXPECT_GT(MeshVolume(repaired.parts[p]), 0) << name << " part " << p;
      EXPECT_TRUE(ClosedAndConsistent(repaired.parts[p])) << name << " part " << p;
    }
  }
  EXPECT_GT(solids, 0);
}

}  // namespace
}  // namespace acdplan::acd
