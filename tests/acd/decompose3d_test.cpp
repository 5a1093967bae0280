#include "acd/decompose3d.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "acd/check_decomposition3d.h"
#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"
#include "solid_test_meshes.h"
#include "tests/acd/problem_lines.h"
#include "tests/asan_build.h"

namespace acdplan::acd {
namespace {

using test::Box;
using test::Concatenate;
using test::IsClosed;
using test::LBlock;
using test::PreparedSolid;
using test::Torus;
using test::UBlock;

int EulerCharacteristic(const TriangleMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  std::set<int> vertices;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      edges.emplace(std::min(a, b), std::max(a, b));
      vertices.insert(a);
    }
  }
  return static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) +
         static_cast<int>(mesh.triangles.rows());
}

// The properties every solid decomposition keeps.
void ExpectValid(const TriangleMesh& input, const Decomposition3d& d, bool capped = false) {
  ASSERT_FALSE(d.components.empty());
  double volume = 0;
  for (size_t i = 0; i < d.components.size(); ++i) {
    const Component3d& c = d.components[i];
    EXPECT_TRUE(IsClosed(c.mesh)) << "component " << i;
    EXPECT_GT(c.volume, 0) << "component " << i;
    EXPECT_NEAR(c.volume, MeshVolume(c.mesh), 1e-9 * (1 + c.volume));
    EXPECT_GE(c.hull_volume, c.volume * (1 - 1e-9)) << "component " << i;
    if (!capped) {
      EXPECT_LE(c.concavity, d.tau * (1 + 1e-9)) << "component " << i;
    }
    volume += c.volume;
  }
  const double expected = MeshVolume(input);
  EXPECT_NEAR(volume, expected, 1e-6 * expected);
  EXPECT_EQ(d.stats.components, static_cast<int>(d.components.size()));
  // The tree: leaves are the components, each once.
  std::set<int> seen;
  for (const HierarchyNode3d& node : d.tree) {
    if (node.children.empty()) {
      EXPECT_GE(node.component, 0);
      seen.insert(node.component);
    }
  }
  EXPECT_EQ(seen.size(), d.components.size());
  // The independent checker agrees (closed, disjoint, inside, concavity re-measured, openings).
  const DecompositionCheck check = CheckDecomposition3d(PreparedSolid(input), d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);
  for (const Opening3d& o : d.openings) {
    EXPECT_LT(o.component_a, o.component_b);
    EXPECT_GT(o.area, 0);
    EXPECT_NEAR(o.normal.norm(), 1.0, 1e-9);
  }
}

Decomposition3d Solve(const TriangleMesh& mesh, double tau, int max_hulls = 0) {
  Decompose3dOptions options;
  options.tau = tau;
  options.max_hulls = max_hulls;
  return Decompose3d(PreparedSolid(mesh), options);
}

TEST(Decompose3d, CubeIsOneConvexComponent) {
  const TriangleMesh cube = Cube(2.0);
  const Decomposition3d d = Solve(cube, 0.01);
  ExpectValid(cube, d);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_EQ(d.components[0].concavity, 0.0);
  EXPECT_NEAR(d.components[0].hull_volume, 8.0, 1e-12);
  EXPECT_TRUE(d.openings.empty());
  EXPECT_FALSE(d.stats.surface);
}

TEST(Decompose3d, ConvexInputAcceptsTauZero) {
  EXPECT_EQ(Solve(Cube(1.0), 0.0).components.size(), 1u);
}

TEST(Decompose3d, LBlockGivesTwoBoxes) {
  const TriangleMesh l = LBlock();
  const Decomposition3d d = Solve(l, 0.05);
  ExpectValid(l, d);
  ASSERT_EQ(d.components.size(), 2u);
  for (const Component3d& c : d.components) EXPECT_NEAR(c.hull_volume, c.volume, 1e-9);
  ASSERT_EQ(d.openings.size(), 1u);
  EXPECT_NEAR(d.openings[0].area, 1.0, 1e-9);
  EXPECT_EQ(ComponentGraph(d), (std::vector<std::vector<int>>{{1}, {0}}));
}

TEST(Decompose3d, UBlockGivesThreeBoxes) {
  const TriangleMesh u = UBlock();
  const Decomposition3d d = Solve(u, 0.05);
  ExpectValid(u, d);
  EXPECT_EQ(d.components.size(), 3u);
  EXPECT_NEAR(d.stats.hull_volume, 5.0, 1e-9);
  EXPECT_EQ(d.openings.size(), 2u);
}

TEST(Decompose3d, TorusIsCutOpenIntoGenusZeroPieces) {
  const TriangleMesh torus = Torus(2.0, 1.0, 24, 12);
  for (double tau : {0.5, 0.2}) {
    const Decomposition3d d = Solve(torus, tau);
    ExpectValid(torus, d);
    EXPECT_GE(d.components.size(), 2u) << "tau " << tau;
    for (const Component3d& c : d.components) EXPECT_EQ(EulerCharacteristic(c.mesh), 2);
  }
}

TEST(Decompose3d, CavityIsCutOpen) {
  const TriangleMesh box = Concatenate(Box({0, 0, 0}, {4, 4, 4}), Box({1, 1, 1}, {3, 3, 3}, true));
  ASSERT_NEAR(MeshVolume(box), 64.0 - 8.0, 1e-12);
  const Decomposition3d d = Solve(box, 0.1);
  ExpectValid(box, d);
  EXPECT_GE(d.components.size(), 2u);
  for (const Component3d& c : d.components) EXPECT_EQ(EulerCharacteristic(c.mesh), 2);
}

// Found by fuzz/fuzz_decompose3d: with coordinates beyond 2^53 (a cube of side 4e16), the
// point-in-solid queries of the nesting of shells and of CheckDecomposition3d() never returned
// (CGAL's query rays were degenerate there; acd/internal/side_of_mesh.h). Scaled up, the
// L block and the box with a cavity decompose as they do at unit size.
TEST(Decompose3d, HugeCoordinatesDecomposeAsAtUnitSize) {
  for (const double scale : {1e17, 1e25}) {
    auto scaled = [&](TriangleMesh mesh) {
      mesh.vertices *= scale;
      return mesh;
    };
    const TriangleMesh l = scaled(LBlock());
    const Decomposition3d dl = Solve(l, 0.05 * scale);
    ExpectValid(l, dl);
    EXPECT_EQ(dl.components.size(), 2u) << "scale " << scale;
    const TriangleMesh unit_box =
        Concatenate(Box({0, 0, 0}, {4, 4, 4}), Box({1, 1, 1}, {3, 3, 3}, true));
    const TriangleMesh box = scaled(unit_box);
    const Decomposition3d db = Solve(box, 0.1 * scale);
    ExpectValid(box, db);
    EXPECT_EQ(db.components.size(), Solve(unit_box, 0.1).components.size()) << "scale " << scale;
  }
}

// What fuzz/fuzz_decompose3d does with a decoded input: PrepareMesh() (repairing or not), the
// solid ACD of a solid, else the surface ACD, at tau_rel x the reference radius, and the check.
struct FuzzedRun {
  PreparedMesh prepared;
  Decomposition3d d;
  DecompositionCheck check;
};
FuzzedRun RunAsTheFuzzerDoes(const TriangleMesh& mesh, bool repair, double tau_rel) {
  FuzzedRun run;
  PrepareMeshOptions prepare;
  prepare.repair = repair;
  run.prepared = PrepareMesh(mesh, prepare);
  Decompose3dOptions options;
  options.tau = tau_rel * ReferenceRadius(run.prepared.mesh);
  options.surface = !run.prepared.solid();
  run.d = Decompose3d(run.prepared, options);
  run.check = CheckDecomposition3d(run.prepared, run.d);
  return run;
}

// A mesh as fuzz_decompose3d decodes it: lattice points times the input's `spacing`.
TriangleMesh FuzzLatticeMesh(std::vector<Eigen::Vector3d> lattice,
                             const std::vector<Eigen::Vector3i>& triangles, double spacing) {
  for (Eigen::Vector3d& p : lattice) p *= spacing;
  return MakeTriangleMesh(lattice, triangles);
}

// Found by fuzz/fuzz_decompose3d (its input decoded here; not a seed of its corpus, as it takes
// longer under the sanitizers than the fuzz step's 10 s limit): two overlapping, warped boxes,
// united by repair. One piece, 0.31 deep against tau 0.12, had no plane among its ranked ones,
// nor among them moved 1e-3 x tau off, whose pieces stayed valid solids once their cut points
// were rounded (a rounded cut face crossed another face), so it was left above tau. The cause
// was an earlier cut whose plane was tangent to a dimple inside its section: its cap passed
// within rounding of the dimple's bottom vertex. SplitByPlane now refuses such a plane, and the
// planes moved farther off (kPlaneShifts) had worked around it; either alone passes this test.
TEST(Decompose3d, APieceWhoseNearPlanesAllRoundInvalidIsStillCut) {
  const std::vector<Eigen::Vector3d> v{
      {0, 0, 8.25},     {4, 0, 0},         {4, 2, 2.75},     {2.5, 3, 3.25},
      {3.5, 3, 3.5},    {3.75, 9.5, 2.25}, {3.25, 2, 3.25},  {3, 2.25, 2.5},
      {3.5, 2.25, 3.5}, {3.25, 3.75, 2.5}, {2.5, 2.5, 3.75}, {2, 6, 2},
      {2, 2, 6},        {6, 2, 0.75},      {6, 6, 6},        {2, 6, 6}};
  const std::vector<Eigen::Vector3i> t{
      {0, 2, 1},   {0, 3, 2},   {4, 5, 6},    {4, 6, 7},    {0, 1, 5},   {0, 5, 4},
      {1, 2, 6},   {1, 6, 5},   {2, 3, 7},    {2, 7, 6},    {3, 0, 4},   {3, 4, 7},
      {8, 10, 9},  {8, 11, 10}, {12, 13, 14}, {12, 14, 15}, {6, 9, 13},  {8, 13, 12},
      {9, 10, 14}, {9, 14, 13}, {15, 4, 10},  {10, 15, 14}, {11, 8, 12}, {11, 12, 15}};
  const FuzzedRun run = RunAsTheFuzzerDoes(MakeTriangleMesh(v, t), true, 0.02);
  ASSERT_TRUE(run.prepared.solid());
  EXPECT_LE(run.d.stats.max_concavity, run.d.tau);
  EXPECT_TRUE(run.check.ok()) << acdplan::test::ProblemLines(run.check);
}

// Found by fuzz/fuzz_decompose3d (fuzz/corpus/decompose3d/regression-sliver-volume-noise.bin):
// LatticeSliver(), a valid tetrahedron whose volume is nothing but rounding. Its one component
// is the tetrahedron itself, whose volume, summed in another vertex order, came out 40% smaller,
// and CheckDecomposition3d() reported a gap: its volume sum had only a relative bound.
TEST(Decompose3d, ASliverWhoseVolumeIsRoundingNoisePassesTheCheck) {
  const FuzzedRun run = RunAsTheFuzzerDoes(test::LatticeSliver(), false, 0.02);
  ASSERT_TRUE(run.prepared.solid());
  ASSERT_LT(MeshVolume(run.prepared.mesh), 1e-30);
  ASSERT_EQ(run.d.components.size(), 1u);
  EXPECT_EQ(run.d.components[0].mesh.vertices.rows(), 4);
  EXPECT_TRUE(run.check.ok()) << acdplan::test::ProblemLines(run.check);
}

// Found by fuzz/fuzz_decompose3d (fuzz/corpus/decompose3d/regression-needle-face-area-noise.bin):
// a surface at coordinates near 1e31, repaired into eight parts, one of them a single needle
// triangle whose area (1.4e45 against the part's squared size of 1e62) is rounding noise. Its
// patch, the same triangle from another first vertex, measured 0, and CheckDecomposition3d()
// reported that the patch areas did not sum to the part's: that sum had only a relative bound.
TEST(Decompose3d, ANeedleFaceWhoseAreaIsRoundingNoisePassesTheCheck) {
  const std::vector<Eigen::Vector3d> v{{-1, -1, 4}, {7, 6, 1}, {2, 8, 1},  {8, 7, 0},
                                       {3, 9, 2},   {9, 8, 3}, {4, 10, 3}, {10, 9, 4},
                                       {5, 0, 0},   {0, 6, 8}, {0, 0, 0},  {16, 0, 0}};
  const std::vector<Eigen::Vector3i> t{
      {4, 5, 0}, {4, 0, 4}, {4, 0, 4}, {4, 0, 0},  {10, 11, 0}, {1, 7, 0},  {7, 6, 1},   {2, 8, 1},
      {8, 7, 2}, {3, 9, 2}, {9, 8, 3}, {4, 10, 3}, {10, 9, 4},  {5, 11, 4}, {11, 10, 5}, {0, 6, 5}};
  const FuzzedRun run = RunAsTheFuzzerDoes(FuzzLatticeMesh(v, t, 1e30), true, 0.2);
  ASSERT_FALSE(run.prepared.solid());
  EXPECT_TRUE(run.check.ok()) << acdplan::test::ProblemLines(run.check);
}

// Found by fuzz/fuzz_decompose3d (fuzz/corpus/decompose3d/regression-needle-hull-at-1e30.bin),
// from the input above: the surface ACD's patch of two triangles whose four corners, 1e30 apart,
// lie within about 1e13 of a line. It measured 0 deep, rightly; CheckDecomposition3d() re-measured
// it 1.1e28 deep against its hull's planes, whose normals, cross products of nearly parallel
// edges, were rounding noise. Its lower bound now takes each plane's rounding off.
TEST(Decompose3d, ANeedlePatchWhoseHullPlanesAreRoundingNoisePassesTheCheck) {
  const std::vector<Eigen::Vector3d> v{{-1, -1, 4}, {7, 6, 1}, {2, 8, 1},  {8, 7, 0},
                                       {3, 9, 2},   {9, 8, 3}, {4, 10, 3}, {10, 9, 4},
                                       {5, 0, 0},   {0, 6, 8}, {0, 16, 0}, {0, 0, 0}};
  const std::vector<Eigen::Vector3i> t{{4, 5, 0}, {4, 0, 4},   {4, 0, 4},  {4, 0, 0},  {8, 0, 0},
                                       {0, 4, 0}, {0, 6, 1},   {2, 8, 1},  {8, 7, 2},  {3, 9, 2},
                                       {8, 8, 3}, {11, 4, 10}, {3, 10, 9}, {4, 5, 11}, {4, 11, 10},
                                       {5, 0, 6}, {5, 6, 11}};
  const FuzzedRun run = RunAsTheFuzzerDoes(FuzzLatticeMesh(v, t, 1e30), true, 0.2);
  ASSERT_FALSE(run.prepared.solid());
  EXPECT_TRUE(run.check.ok()) << acdplan::test::ProblemLines(run.check);
}

// A valid solid whose cavity touches its outer surface at a corner. Before PrepareMesh() gave
// each fan there its own vertex, no cut could split the piece holding both fans (they round to
// one position, which RoundsToValidSolid() refuses): the L was output whole, 4 x tau deep, and
// CheckDecomposition3d() found it non-manifold.
TEST(Decompose3d, ACavityTouchingTheSurfaceAtAVertexIsCutOpen) {
  const TriangleMesh l = LBlock();
  const int corner = test::VertexAt(l, {2, 0, 1});
  ASSERT_GE(corner, 0);
  const TriangleMesh solid = test::WithCavityAtCorner(l, corner, {-1, 1, -1}, 0.25);
  for (const double tau_rel : {0.2, 0.05}) {
    const FuzzedRun run = RunAsTheFuzzerDoes(solid, false, tau_rel);
    ASSERT_TRUE(run.prepared.solid()) << run.prepared.defects.first;
    EXPECT_TRUE(run.check.ok()) << "tau_rel " << tau_rel << "\n"
                                << acdplan::test::ProblemLines(run.check);
    EXPECT_GE(run.d.components.size(), 2u);
    for (const Component3d& c : run.d.components) EXPECT_EQ(EulerCharacteristic(c.mesh), 2);
  }
}

// One shell that touches itself: a square pyramid dented into the top of a 4 x 4 x 2 box, its
// apex on the centre vertex of the bottom face. The dent's fan (the solid outside its cone)
// moves up into the dent; the bottom's stays.
TEST(Decompose3d, ADentWhoseTipTouchesTheBottomIsCutLikeAnyOther) {
  const std::vector<Eigen::Vector3d> v{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {2, 2, 0},
                                       {0, 0, 2}, {4, 0, 2}, {4, 4, 2}, {0, 4, 2}, {1, 1, 2},
                                       {3, 1, 2}, {3, 3, 2}, {1, 3, 2}};
  std::vector<Eigen::Vector3i> t;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    t.emplace_back(4, j, i);      // bottom
    t.emplace_back(i, j, j + 5);  // sides
    t.emplace_back(i, j + 5, i + 5);
    t.emplace_back(i + 5, j + 5, j + 9);  // top, around the dent
    t.emplace_back(i + 5, j + 9, i + 9);
    t.emplace_back(i + 9, j + 9, 4);  // the dent
  }
  const TriangleMesh dented = MakeTriangleMesh(v, t);
  ASSERT_NEAR(MeshVolume(dented), 32.0 - 8.0 / 3, 1e-12);
  for (const double tau_rel : {0.2, 0.05}) {
    const FuzzedRun run = RunAsTheFuzzerDoes(dented, false, tau_rel);
    ASSERT_TRUE(run.prepared.solid()) << run.prepared.defects.first;
    ASSERT_EQ(run.prepared.mesh.vertices.rows(), 14);  // The apex and its copy.
    EXPECT_TRUE(run.check.ok()) << "tau_rel " << tau_rel << "\n"
                                << acdplan::test::ProblemLines(run.check);
    EXPECT_GE(run.d.components.size(), 2u);
  }
}

// Found by fuzz/fuzz_decompose3d
// (fuzz/corpus/decompose3d/regression-cavity-touching-its-shell.bin): repair unites two
// self-crossing shells at 1e30 into one part with a cavity that touches the outer shell at two
// vertices. The cavity's owner after each cut was decided by ray parity from its first vertex, one
// of those two: it came out as a component of its own, inside out
// ("mesh is inward-oriented"). Now PrepareMesh() separates the fans, ConnectedSolids() decides
// the nesting exactly, and a cut that leaves an inward piece is refused.
TEST(Decompose3d, ACavityTouchingItsShellIsNeverAComponentOfItsOwn) {
  const std::vector<Eigen::Vector3d> v{{-1, 65, 4}, {7, 1, 8}, {1, 8, 6},  {9, 2, 2},
                                       {3, 7, 2},   {9, 6, 3}, {4, 10, 3}, {5, 4, 10},
                                       {0, 9, 0},   {0, 6, 8}, {0, 0, 0},  {16, 0, 0}};
  const std::vector<Eigen::Vector3i> t{{4, 5, 0}, {4, 0, 4},   {0, 0, 4},  {4, 0, 0},   {10, 11, 0},
                                       {1, 7, 0}, {7, 6, 1},   {2, 8, 1},  {8, 7, 2},   {3, 6, 2},
                                       {9, 8, 3}, {4, 10, 3},  {10, 9, 4}, {5, 11, 10}, {11, 0, 1},
                                       {7, 0, 7}, {6, 1, 2},   {8, 1, 8},  {7, 2, 3},   {9, 2, 9},
                                       {8, 3, 4}, {10, 3, 10}, {9, 4, 4},  {11, 11, 5}, {0, 6, 5}};
  const FuzzedRun run = RunAsTheFuzzerDoes(FuzzLatticeMesh(v, t, 1e30), true, 0.2);
  ASSERT_TRUE(run.prepared.solid()) << run.prepared.defects.first;
  EXPECT_TRUE(run.check.ok()) << acdplan::test::ProblemLines(run.check);
  for (const Component3d& c : run.d.components) EXPECT_GT(c.volume, 0);
}

// Found by fuzz/fuzz_decompose3d
// (fuzz/corpus/decompose3d/regression-pinch-too-small-to-separate.bin), from the input above:
// repair leaves a vertex whose shortest edges are a few units in the last place of its coordinates
// (1e30), where the part meets itself in two fans. 1e-3 of those edges moves nothing in doubles, so
// the copies rounded back onto the vertex, and the part went to the solid ACD pinched
// (CheckDecomposition3d: "not a 2-manifold"). Such a pinch is now a defect, and the mesh gets the
// surface ACD.
TEST(Decompose3d, APinchTooSmallToSeparateIsADefect) {
  const std::vector<Eigen::Vector3d> v{{-1, -1, 4}, {7, 1, 8},   {1, 8, 6},  {9, 2, 2},
                                       {3, 7, 2},   {9, 6, 3},   {4, 10, 3}, {5, 4, 10},
                                       {0, 9, 0},   {115, 6, 8}, {0, 0, 0},  {16, 0, 0}};
  const std::vector<Eigen::Vector3i> t{{4, 5, 0}, {4, 0, 4},   {0, 0, 4},  {4, 0, 0},   {10, 11, 0},
                                       {1, 7, 0}, {7, 6, 1},   {2, 8, 1},  {8, 7, 2},   {3, 6, 2},
                                       {9, 8, 3}, {4, 10, 3},  {10, 9, 4}, {5, 11, 10}, {11, 0, 1},
                                       {7, 0, 7}, {6, 1, 2},   {8, 1, 8},  {7, 2, 3},   {9, 2, 9},
                                       {8, 3, 4}, {10, 3, 10}, {9, 4, 4},  {11, 10, 5}, {0, 6, 5}};
  const FuzzedRun run = RunAsTheFuzzerDoes(FuzzLatticeMesh(v, t, 1e30), true, 0.2);
  ASSERT_FALSE(run.prepared.solid());
  EXPECT_EQ(run.prepared.defects.pinch_vertices, 1);
  EXPECT_THAT(run.prepared.defects.first, ::testing::HasSubstr(" is a pinch: the surface meets"));
  EXPECT_TRUE(run.check.ok()) << acdplan::test::ProblemLines(run.check);
}

TEST(Decompose3d, SameInputSameBytes) {
  const TriangleMesh torus = Torus(2.0, 1.0, 16, 8);
  const Decomposition3d a = Solve(torus, 0.3), b = Solve(torus, 0.3);
  ASSERT_EQ(a.components.size(), b.components.size());
  for (size_t i = 0; i < a.components.size(); ++i) {
    const TriangleMesh& x = a.components[i].mesh;
    const TriangleMesh& y = b.components[i].mesh;
    ASSERT_EQ(x.vertices.rows(), y.vertices.rows());
    EXPECT_EQ(std::memcmp(x.vertices.data(), y.vertices.data(),
                          sizeof(double) * static_cast<size_t>(x.vertices.size())),
              0);
    EXPECT_TRUE(x.triangles == y.triangles);
  }
}

TEST(Decompose3d, MaxHullsMergesAlongTheTree) {
#if ACDPLAN_ASAN_BUILD
  const TriangleMesh torus = Torus(2.0, 1.0, 12, 6);  // the sanitizer build is ~10x slower
#else
  const TriangleMesh torus = Torus(2.0, 1.0, 24, 12);
#endif
  const Decomposition3d full = Solve(torus, 0.1);
  ASSERT_GT(full.components.size(), 4u);
  const Decomposition3d capped = Solve(torus, 0.1, 4);
  ExpectValid(torus, capped, /*capped=*/true);
  EXPECT_LE(capped.components.size(), 4u);
  EXPECT_EQ(capped.max_hulls, 4);
  EXPECT_GE(capped.stats.hull_volume, full.stats.hull_volume * (1 - 1e-9));
}

TEST(Decompose3d, FeatureGroupingKeepsTheKnownAnswers) {
  // The global cut's plane joins the candidates; the blocks still split into their boxes (the
  // walls extended win ties) and every result passes the same checks.
  auto solve = [](const TriangleMesh& mesh, double tau) {
    Decompose3dOptions options;
    options.tau = tau;
    options.feature_grouping = true;
    return Decompose3d(PreparedSolid(mesh), options);
  };
  const TriangleMesh l = LBlock(), u = UBlock(), torus = Torus(2.0, 1.0, 16, 8);
  const Decomposition3d dl = solve(l, 0.05), du = solve(u, 0.05), dt = solve(torus, 0.3);
  ExpectValid(l, dl);
  ASSERT_EQ(dl.components.size(), 2u);
  ASSERT_EQ(dl.openings.size(), 1u);
  EXPECT_NEAR(dl.openings[0].area, 1.0, 1e-9);
  ExpectValid(u, du);
  EXPECT_EQ(du.components.size(), 3u);
  ExpectValid(torus, dt);
  EXPECT_GE(dt.components.size(), 2u);
  for (const Component3d& c : dt.components) EXPECT_EQ(EulerCharacteristic(c.mesh), 2);
  // Deterministic like the default.
  const Decomposition3d again = solve(torus, 0.3);
  ASSERT_EQ(again.components.size(), dt.components.size());
  for (size_t i = 0; i < dt.components.size(); ++i) {
    EXPECT_TRUE(again.components[i].mesh.vertices == dt.components[i].mesh.vertices);
  }
}

TEST(Decompose3d, RejectsBadOptions) {
  const PreparedMesh cube = PreparedSolid(Cube(1.0));
  Decompose3dOptions options;
  options.tau = -1;
  EXPECT_THROW(
      {
        try {
          Decompose3d(cube, options);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("tau must be a finite number >= 0"),
                    std::string::npos);
          throw;
        }
      },
      InputError);
  options.tau = 0.1;
  options.max_hulls = -2;
  EXPECT_THROW(Decompose3d(cube, options), InputError);
  options.max_hulls = 0;
  EXPECT_THROW(Decompose3d(PreparedMesh{}, options), InputError);
  // tau 0 on a non-convex part would cut forever.
  EXPECT_THROW(Solve(LBlock(), 0.0), InputError);
}

}  // namespace
}  // namespace acdplan::acd
