// Same input and options give the same output, byte for byte: the repaired mesh and the solid
// ACD on it, computed several times in one process with the heap in different states. The
// union that repairs crossing shells came in CGAL's vertex and face order, which follows heap
// addresses; exact (Epeck) points were rounded with CGAL::to_double, whose result depends on
// what was evaluated exactly before (see RoundToDouble()); the hulls' triangles came in the
// diagonals CGAL's convex_hull_3 draws across coplanar facets, which follow heap addresses too.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "acd/decompose3d.h"
#include "acd/decomposition3d_io.h"
#include "acd/prepare_mesh.h"
#include "envs/mesh_loader.h"
#include "solid_test_meshes.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

using test::Bytes;

std::string Bytes(const PreparedMesh& prepared) {
  std::string bytes = Bytes(prepared.mesh);
  for (const TriangleMesh& part : prepared.parts) bytes += Bytes(part);
  for (const std::string& note : prepared.notes) bytes += note + "\n";
  return bytes + prepared.defects.first;
}

PreparedMesh Repaired(const TriangleMesh& mesh) {
  PrepareMeshOptions options;
  options.repair = true;
  return PrepareMesh(mesh, options);
}

// Heap blocks of varied sizes kept alive across a run, so that the next run's allocations land
// elsewhere (results must not depend on addresses either).
std::vector<std::unique_ptr<char[]>> Garbage(int run) {
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < 50 * run; ++i) {
    blocks.emplace_back(new char[static_cast<size_t>(24 + 40 * i)]);
    std::memset(blocks.back().get(), 0x5a, static_cast<size_t>(24 + 40 * i));
  }
  return blocks;
}

TEST(ReproducibilityTest, RepairedTeapotIsTheSameEveryTime) {
  // Holes filled, then 4 crossing shells united by the exact winding rule.
  const TriangleMesh teapot = envs::ReadMesh(acdplan::test::DataDir() + "/meshes/vhacd/teapot.obj");
  const PreparedMesh first = Repaired(teapot);
  ASSERT_TRUE(first.solid()) << first.defects.first;
  const std::string expected = Bytes(first);
  for (int run = 1; run <= 3; ++run) {
    const auto garbage = Garbage(run);
    EXPECT_TRUE(Bytes(Repaired(teapot)) == expected) << "run " << run << " differs from run 0";
  }
}

TEST(ReproducibilityTest, SolidAcdOfUnitedTiltedBoxesIsTheSameEveryTime) {
  // An L-block crossed by a tilted box: the union's vertices are rounded exact intersection
  // points, and the cuts of the ACD construct more of them.
  TriangleMesh tilted = test::Box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                                    Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  for (Eigen::Index v = 0; v < tilted.vertices.rows(); ++v) {
    const Eigen::Vector3d p = rotation * tilted.vertices.row(v).transpose();
    tilted.vertices.row(v) = (p + Eigen::Vector3d(1.6, 0.9, 0.8)).transpose();
  }
  const TriangleMesh mesh = test::Concatenate(test::LBlock(), tilted);

  auto run_once = [&mesh](int run) {
    const auto garbage = Garbage(run);
    const PreparedMesh prepared = Repaired(mesh);
    Decompose3dOptions options;
    options.tau = 0.02 * ReferenceRadius(prepared.mesh);
    Decomposition3d decomposition = Decompose3d(prepared, options);
    decomposition.stats.time_ms = 0;  // Wall-clock time.
    return std::make_pair(Bytes(prepared), Decomposition3dToJson(decomposition, {"mesh", 0.02}));
  };
  const auto [mesh_bytes, json] = run_once(0);
  const PreparedMesh prepared = Repaired(mesh);
  ASSERT_TRUE(prepared.solid()) << prepared.defects.first;
  ASSERT_EQ(prepared.parts.size(), 1u);
  const Decomposition3d decomposition =
      Decompose3d(prepared, {0.02 * ReferenceRadius(prepared.mesh)});
  ASSERT_GE(decomposition.components.size(), 3u);  // The L's notch and the box get cut.
  for (int run = 1; run <= 3; ++run) {
    const auto [other_mesh, other_json] = run_once(run);
    EXPECT_TRUE(other_mesh == mesh_bytes) << "run " << run << ": the repaired mesh differs";
    EXPECT_TRUE(other_json == json) << "run " << run << ": the decomposition differs";
  }
}

}  // namespace
}  // namespace acdplan::acd
