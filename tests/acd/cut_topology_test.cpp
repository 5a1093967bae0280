#include "acd/internal/cut_topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acd/internal/exact_plane_split.h"
#include "base/random.h"
#include "solid_test_meshes.h"
#include "tests/data_paths.h"

namespace acdplan::acd::internal {
namespace {

// What the exact cut leaves: SplitByPlane, then each side's connected solids.
CutTopology ExactCut(const TriangleMesh& mesh, const Plane3d& plane) {
  const ExactKernel::Plane_3 exact(plane.normal.x(), plane.normal.y(), plane.normal.z(),
                                   -plane.offset);
  ExactPiece below, above;
  SplitByPlane(ToExact(mesh), exact, &below, &above);
  CutTopology out;
  for (const ExactPiece* side : {&below, &above}) {
    if (side->triangles.empty()) continue;
    for (const ExactPiece& piece : ConnectedSolids(*side)) {
      ++out.pieces;
      out.genus += Topology(piece.triangles).genus;
    }
  }
  return out;
}

Plane3d PlaneOf(const Eigen::Vector3d& normal, double offset) {
  return {normal.normalized(), offset};
}

TEST(PredictCutTopology, TorusCutsWithKnownAnswers) {
  const TriangleMesh torus = test::Torus(2, 0.5, 32, 16);
  struct Case {
    const char* what;
    Plane3d plane;
    int pieces, genus;
  };
  const std::vector<Case> cases = {
      {"above it", PlaneOf({0, 0, 1}, 0.6), 1, 1},
      {"along the ring (an annulus: two rings)", PlaneOf({0, 0, 1}, 0.1), 2, 2},
      {"through the axis (two discs)", PlaneOf({1, 0, 0.01}, 0.05), 2, 0},
      {"across the hole (two discs)", PlaneOf({1, 0, 0.01}, 1.0), 2, 0},
      {"through the tube on one side (one region: the rest stays a ring)",
       PlaneOf({1, 0.01, 0}, 1.8), 2, 1},
  };
  for (const Case& c : cases) {
    const std::optional<CutTopology> predicted = PredictCutTopology(torus, 1, c.plane);
    ASSERT_TRUE(predicted.has_value()) << c.what;
    EXPECT_EQ(predicted->pieces, c.pieces) << c.what;
    EXPECT_EQ(predicted->genus, c.genus) << c.what;
    const CutTopology exact = ExactCut(torus, c.plane);
    EXPECT_EQ(exact.pieces, c.pieces) << c.what;
    EXPECT_EQ(exact.genus, c.genus) << c.what;
  }
}

TEST(PredictCutTopology, NoPredictionForAPlaneThroughAFace) {
  const TriangleMesh box = test::Box({0, 0, 0}, {1, 1, 1});
  EXPECT_FALSE(PredictCutTopology(box, 0, PlaneOf({0, 0, 1}, 1)).has_value());
  EXPECT_TRUE(PredictCutTopology(box, 0, PlaneOf({0, 0, 1}, 0.5)).has_value());
}

// Every prediction made equals the exact cut, for planes at random and planes through a vertex
// (whose height rounds to about 0: the uncertain case), on a cup and meshes with handles.
TEST(PredictCutTopology, EqualsTheExactCutWheneverItPredicts) {
  const std::string dir = acdplan::test::DataDir() + "/meshes/vhacd/";
  const std::vector<std::pair<std::string, TriangleMesh>> meshes = {
      {"torus", test::Torus(2, 0.5, 24, 12)},
      {"torus1", test::ReadObjForTest(dir + "torus1.obj")},
      {"torus2", test::ReadObjForTest(dir + "torus2.obj")},
      {"cup", test::ReadObjForTest(dir + "cup.obj")},
  };
  RandomEngine rng(20261202);
  int predicted_count = 0, through_vertex = 0;
  for (const auto& [name, mesh] : meshes) {
    ASSERT_GT(mesh.vertices.rows(), 0) << name;
    const ShellTopology topology = Topology(ToExact(mesh).triangles);
    ASSERT_EQ(topology.shells, 1) << name;
    for (int trial = 0; trial < 24; ++trial) {
      Eigen::Vector3d normal;
      for (int k = 0; k < 3; ++k) normal(k) = StandardNormal(rng);
      normal.normalize();
      const auto v = static_cast<Eigen::Index>(
          UniformIndex(rng, static_cast<std::uint64_t>(mesh.vertices.rows())));
      const Eigen::Vector3d p = mesh.vertices.row(v);
      const bool at_vertex = trial % 2 == 0;
      const double offset = normal.dot(p) + (at_vertex ? 0.0 : 1e-3 * UniformReal(rng, -1, 1));
      const Plane3d plane{normal, offset};
      const std::optional<CutTopology> predicted = PredictCutTopology(mesh, topology.genus, plane);
      if (!predicted) continue;
      ++predicted_count;
      through_vertex += at_vertex;
      const CutTopology exact = ExactCut(mesh, plane);
      EXPECT_EQ(predicted->genus, exact.genus) << name << " trial " << trial;
    }
  }
  // Most planes get a prediction, those through a vertex too.
  EXPECT_GT(predicted_count, 60);
  EXPECT_GT(through_vertex, 25);
}

}  // namespace
}  // namespace acdplan::acd::internal
