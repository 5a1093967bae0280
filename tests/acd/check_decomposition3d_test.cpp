#include "acd/check_decomposition3d.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/mesh_measures.h"
#include "tests/acd/problem_lines.h"

namespace acdplan::acd {
namespace {

// The box [lo, hi], outward (Cube's triangles, scaled and moved).
TriangleMesh Box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  TriangleMesh box = Cube(1.0);
  for (Eigen::Index v = 0; v < box.vertices.rows(); ++v) {
    const Eigen::Vector3d p = box.vertices.row(v).transpose();
    box.vertices.row(v) =
        (lo + (p + Eigen::Vector3d::Constant(0.5)).cwiseProduct(hi - lo)).transpose();
  }
  return box;
}

std::vector<Eigen::Vector3d> Points(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    points.push_back(mesh.vertices.row(v).transpose());
  }
  return points;
}

// A component with its hull and stored figures computed from `mesh` (concavity 0).
Component3d Solid(const TriangleMesh& mesh, int source = 0) {
  Component3d c;
  c.mesh = mesh;
  c.hull = ConvexHull3(Points(mesh), 0.0);
  c.centroid = MeshCentroid(mesh, true);
  c.volume = MeshVolume(mesh);
  c.hull_volume = MeshVolume(c.hull);
  c.source = source;
  return c;
}

void FillStats(Decomposition3d* d) {
  d->stats = {};
  d->stats.components = static_cast<int>(d->components.size());
  for (const Component3d& c : d->components) {
    d->stats.volume += c.volume;
    d->stats.hull_volume += c.hull_volume;
    d->stats.max_concavity = std::max(d->stats.max_concavity, c.concavity);
  }
}

// A root with one leaf per component.
void FillTree(Decomposition3d* d) {
  d->tree.assign(1, {});
  d->roots = {0};
  if (d->components.size() == 1) {
    d->tree[0].component = 0;
    return;
  }
  for (size_t i = 0; i < d->components.size(); ++i) {
    HierarchyNode3d leaf;
    leaf.parent = 0;
    leaf.depth = 1;
    leaf.component = static_cast<int>(i);
    d->tree[0].children.push_back(static_cast<int>(d->tree.size()));
    d->tree.push_back(leaf);
  }
}

PreparedMesh Prepared(const TriangleMesh& mesh) {
  PreparedMesh prepared;
  prepared.mesh = mesh;
  prepared.parts = {mesh};
  return prepared;
}

// The box [0,2]x[0,1]x[0,1] split at x = 1 into two boxes sharing the square opening.
struct SplitBox {
  PreparedMesh input = Prepared(Box({0, 0, 0}, {2, 1, 1}));
  Decomposition3d d;
  SplitBox() {
    d.tau = 0.1;
    d.components = {Solid(Box({0, 0, 0}, {1, 1, 1})), Solid(Box({1, 0, 0}, {2, 1, 1}))};
    Opening3d opening;
    opening.polygon = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}};
    opening.normal = Eigen::Vector3d::UnitX();
    opening.area = 1.0;
    opening.component_a = 0;
    opening.component_b = 1;
    d.openings = {opening};
    FillTree(&d);
    FillStats(&d);
  }
};

// The check reports a problem containing `needle`.
void ExpectProblem(const DecompositionCheck& check, const std::string& needle) {
  EXPECT_NE(acdplan::test::ProblemLines(check).find(needle), std::string::npos)
      << "expected a problem with '" << needle << "', got:\n"
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecomposition3dTest, BoxSplitIntoTwoBoxesIsValid) {
  const SplitBox box;
  const DecompositionCheck check = CheckDecomposition3d(box.input, box.d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);
}

TEST(CheckDecomposition3dTest, ReportsAGap) {
  SplitBox box;
  box.d.components.pop_back();
  box.d.openings.clear();
  FillTree(&box.d);
  FillStats(&box.d);
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "(a gap)");
}

TEST(CheckDecomposition3dTest, ReportsAnOverlapTheVolumesHide) {
  // B moved half into A: the volumes still sum to 2, the samples see the overlap.
  SplitBox box;
  box.d.components[1] = Solid(Box({0.5, 0, 0}, {1.5, 1, 1}));
  box.d.openings.clear();
  FillStats(&box.d);
  const DecompositionCheck check = CheckDecomposition3d(box.input, box.d);
  ExpectProblem(check, "components 0 and 1 overlap");
  EXPECT_EQ(acdplan::test::ProblemLines(check).find("(a gap)"), std::string::npos);
}

TEST(CheckDecomposition3dTest, ReportsAComponentOutsideTheInput) {
  SplitBox box;
  box.d.components[1] = Solid(Box({1, 0, 0}, {2, 1, 1.5}));
  box.d.openings.clear();
  FillStats(&box.d);
  const DecompositionCheck check = CheckDecomposition3d(box.input, box.d);
  ExpectProblem(check, "lies outside the input part");
  ExpectProblem(check, "(an overlap)");
}

TEST(CheckDecomposition3dTest, ReportsAnOpenComponent) {
  SplitBox box;
  TriangleMesh& mesh = box.d.components[0].mesh;
  mesh.triangles.conservativeResize(mesh.triangles.rows() - 1, 3);
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "component 0: mesh is not closed");
}

TEST(CheckDecomposition3dTest, ReportsAFlippedComponent) {
  SplitBox box;
  TriangleMesh& mesh = box.d.components[1].mesh;
  mesh.triangles.col(1).swap(mesh.triangles.col(2));
  box.d.components[1].volume = MeshVolume(mesh);
  FillStats(&box.d);
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "component 1: mesh is inward-oriented");
}

TEST(CheckDecomposition3dTest, ReportsASelfIntersectingComponent) {
  // Two boxes crossing each other, both closed and outward: one mesh, self-intersecting.
  SplitBox box;
  const TriangleMesh a = Box({0, 0, 0}, {1, 1, 1}), b = Box({0.25, 0.25, 0.25}, {0.75, 0.75, 1.5});
  TriangleMesh both;
  both.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  both.vertices << a.vertices, b.vertices;
  both.triangles.resize(a.triangles.rows() + b.triangles.rows(), 3);
  both.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.rows()));
  box.d.components[0] = Solid(both);
  FillStats(&box.d);
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "component 0: mesh self-intersects");
}

TEST(CheckDecomposition3dTest, ReportsAHullThatDoesNotContainItsMesh) {
  SplitBox box;
  box.d.components[0].hull = Box({0, 0, 0}, {0.5, 1, 1});
  box.d.components[0].hull_volume = 0.5;
  FillStats(&box.d);
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "lies outside the hull (by 0.5)");
}

TEST(CheckDecomposition3dTest, ReportsWrongStoredFigures) {
  SplitBox box;
  box.d.components[0].volume = 1.5;
  box.d.components[1].centroid.x() += 0.1;
  box.d.components[1].hull_volume = 2.0;
  FillStats(&box.d);
  const DecompositionCheck check = CheckDecomposition3d(box.input, box.d);
  ExpectProblem(check, "component 0: volume 1.5 != 1 (MeshVolume)");
  ExpectProblem(check, "component 1: centroid (1.6, 0.5, 0.5) != (1.5, 0.5, 0.5)");
  ExpectProblem(check, "component 1: hull_volume 2 != 1");
  box.d.stats.components = 3;
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "stats.components 3 != 2 components");
}

TEST(CheckDecomposition3dTest, ReportsAnOpeningOffTheBoundary) {
  SplitBox box;
  for (Eigen::Vector3d& p : box.d.openings[0].polygon) p.x() = 1.5;
  ExpectProblem(CheckDecomposition3d(box.input, box.d),
                "opening 0: vertex (1.5, 0, 0) is not on the boundary of component 0 (distance "
                "0.5)");
  SplitBox flipped;
  std::swap(flipped.d.openings[0].polygon[1], flipped.d.openings[0].polygon[3]);
  ExpectProblem(CheckDecomposition3d(flipped.input, flipped.d),
                "is not the polygon's counter-clockwise normal");
  SplitBox same;
  same.d.openings[0].component_b = 0;
  ExpectProblem(CheckDecomposition3d(same.input, same.d), "are not two component indices a < b");
}

TEST(CheckDecomposition3dTest, OpeningHolesCountInTheAreaAndMustRunClockwise) {
  // The square opening at x = 1 with a square hole of area 0.25: clockwise seen from +x.
  const std::vector<Eigen::Vector3d> hole = {
      {1, 0.25, 0.25}, {1, 0.25, 0.75}, {1, 0.75, 0.75}, {1, 0.75, 0.25}};
  SplitBox holed;
  holed.d.openings[0].holes = {hole};
  holed.d.openings[0].area = 0.75;
  EXPECT_TRUE(CheckDecomposition3d(holed.input, holed.d).ok());
  SplitBox area;
  area.d.openings[0].holes = {hole};  // Area still 1.
  ExpectProblem(CheckDecomposition3d(area.input, area.d), "area 1 != polygon area 0.75");
  SplitBox counter;
  counter.d.openings[0].holes = {{hole.rbegin(), hole.rend()}};
  counter.d.openings[0].area = 0.75;
  ExpectProblem(CheckDecomposition3d(counter.input, counter.d),
                "opening 0: hole 0 is not a clockwise polygon about the normal");
}

TEST(CheckDecomposition3dTest, ReportsConcavityAboveTau) {
  // An L-shaped solid stored as one component: its inner corner lies 0.5 deep in its hull.
  const TriangleMesh l_block = [] {
    // The L's profile in the xy-plane, extruded along z; triangles by hand, outward.
    const std::vector<Eigen::Vector3d> profile = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0},
                                                  {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    std::vector<Eigen::Vector3d> v;
    for (double z : {0.0, 1.0}) {
      for (Eigen::Vector3d p : profile) v.push_back({p.x(), p.y(), z});
    }
    std::vector<Eigen::Vector3i> t = {{0, 2, 1}, {0, 3, 2}, {0, 5, 3},  {5, 4, 3},     // bottom
                                      {6, 7, 8}, {6, 8, 9}, {6, 9, 11}, {11, 9, 10}};  // top
    for (int i = 0; i < 6; ++i) {
      const int j = (i + 1) % 6;
      t.push_back({i, j, j + 6});
      t.push_back({i, j + 6, i + 6});
    }
    return MakeTriangleMesh(v, t);
  }();
  ASSERT_NEAR(MeshVolume(l_block), 3.0, 1e-12);
  Decomposition3d d;
  d.tau = 0.1;
  d.components = {Solid(l_block)};
  FillTree(&d);
  FillStats(&d);
  const PreparedMesh input = Prepared(l_block);
  ExpectProblem(CheckDecomposition3d(input, d),
                "component 0: concavity 0 is below its re-measured lower bound");
  d.components[0].concavity = 0.5;
  FillStats(&d);
  ExpectProblem(CheckDecomposition3d(input, d), "component 0: concavity 0.5 > tau 0.1");
  d.tau = 0.5;
  EXPECT_TRUE(CheckDecomposition3d(input, d).ok())
      << acdplan::test::ProblemLines(CheckDecomposition3d(input, d));
  d.tau = 0.1;
  d.max_hulls = 1;  // A cap merged it: tau no longer binds.
  EXPECT_TRUE(CheckDecomposition3d(input, d).ok())
      << acdplan::test::ProblemLines(CheckDecomposition3d(input, d));
}

TEST(CheckDecomposition3dTest, ReportsBrokenTrees) {
  // Two leaves may share a component (the merge pass unites leaves), but then component 1
  // is no leaf's; a leaf must name a component.
  SplitBox box;
  box.d.tree[2].component = 0;
  ExpectProblem(CheckDecomposition3d(box.input, box.d), "component 1: is the leaf of no tree node");
  box.d.tree[2].component = 2;
  ExpectProblem(CheckDecomposition3d(box.input, box.d),
                "tree node 2: leaf without a component (2)");
}

// Surface ACD results: a square of two triangles as one patch and as two.
struct SplitSquare {
  PreparedMesh input;
  Decomposition3d d;
  SplitSquare() {
    const TriangleMesh square =
        MakeTriangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    input = Prepared(square);
    input.defects.boundary_edges = 4;
    d.tau = 0.0;
    for (int f = 0; f < 2; ++f) {
      Component3d c;
      c.mesh = MakeTriangleMesh({square.vertices.row(0).transpose(),
                                 square.vertices.row(square.triangles(f, 1)).transpose(),
                                 square.vertices.row(square.triangles(f, 2)).transpose()},
                                {{0, 1, 2}});
      c.hull = ConvexHull3(Points(c.mesh), 0.0);  // Flat and one-sided: add the other side.
      const Eigen::Index n = c.hull.triangles.rows();
      c.hull.triangles.conservativeResize(2 * n, 3);
      c.hull.triangles.bottomRows(n) = c.hull.triangles.topRows(n).rowwise().reverse();
      c.centroid = MeshCentroid(c.mesh, false);
      c.hull_volume = MeshVolume(c.hull);
      d.components.push_back(c);
    }
    Opening3d opening;
    opening.polygon = {{0, 0, 0}, {1, 1, 0}};
    opening.component_a = 0;
    opening.component_b = 1;
    d.openings = {opening};
    FillTree(&d);
    FillStats(&d);
    d.stats.surface = true;
  }
};

TEST(CheckDecomposition3dTest, SurfacePatchesThatPartitionTheFacesAreValid) {
  const SplitSquare square;
  const DecompositionCheck check = CheckDecomposition3d(square.input, square.d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);
}

TEST(CheckDecomposition3dTest, ReportsSurfaceFacesMissingOrTwice) {
  SplitSquare missing;
  missing.d.components.pop_back();
  missing.d.openings.clear();
  FillTree(&missing.d);
  FillStats(&missing.d);
  missing.d.stats.surface = true;
  ExpectProblem(CheckDecomposition3d(missing.input, missing.d), "part 0: 1 faces are in no patch");
  SplitSquare twice;
  twice.d.components[1] = twice.d.components[0];
  FillStats(&twice.d);
  twice.d.stats.surface = true;
  ExpectProblem(CheckDecomposition3d(twice.input, twice.d),
                "component 1: triangle 0 at (0, 0, 0) is already in another patch");
}

TEST(CheckDecomposition3dTest, ReportsSurfaceOpeningsThatAreNotSharedEdges) {
  SplitSquare square;
  square.d.openings[0].polygon = {{0, 0, 0}, {1, 0, 0}};
  ExpectProblem(CheckDecomposition3d(square.input, square.d),
                "segment (0, 0, 0)-(1, 0, 0) is not an edge of component 1");
  SplitSquare area;
  area.d.openings[0].area = 1.0;
  ExpectProblem(CheckDecomposition3d(area.input, area.d),
                "a surface opening has area 0 and a zero normal");
  SplitSquare holes;
  holes.d.openings[0].holes = {{{0.2, 0.2, 0}, {0.2, 0.4, 0}, {0.4, 0.2, 0}}};
  ExpectProblem(CheckDecomposition3d(holes.input, holes.d), "a surface opening has no holes");
}

TEST(CheckDecomposition3dTest, ReportsTheSolidAcdOnANonSolidInput) {
  SplitSquare square;
  square.d.stats.surface = false;
  square.input.defects.first = "edge 0-1 has 1 face";
  ExpectProblem(CheckDecomposition3d(square.input, square.d),
                "the input is not a solid (edge 0-1 has 1 face) but the solid ACD was used");
}

}  // namespace
}  // namespace acdplan::acd
