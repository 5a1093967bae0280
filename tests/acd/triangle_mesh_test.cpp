#include "acd/triangle_mesh.h"

#include <gtest/gtest.h>

#include "acd/mesh_measures.h"
#include "solid_test_meshes.h"

namespace acdplan::acd {
namespace {

TEST(CanonicallyNumbered, TwoNumberingsOfOneMeshGiveTheSameBytes) {
  const TriangleMesh block = test::UBlock();
  const std::string canonical = test::Bytes(CanonicallyNumbered(block));
  for (std::uint64_t seed : {1, 2, 3}) {
    EXPECT_EQ(test::Bytes(CanonicallyNumbered(test::Renumbered(block, seed))), canonical)
        << "seed " << seed;
  }
}

TEST(CanonicallyNumbered, KeepsTheSolidAndSortsItsElements) {
  const TriangleMesh torus = test::Torus(2.0, 1.0, 10, 6);
  const TriangleMesh out = CanonicallyNumbered(torus);
  EXPECT_TRUE(test::IsClosed(out));
  EXPECT_DOUBLE_EQ(MeshVolume(out), MeshVolume(torus));  // orientation kept
  for (Eigen::Index i = 1; i < out.vertices.rows(); ++i) {
    const Eigen::Vector3d a = out.vertices.row(i - 1), b = out.vertices.row(i);
    EXPECT_TRUE(std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z()));
  }
  for (Eigen::Index f = 0; f < out.triangles.rows(); ++f) {
    EXPECT_LT(out.triangles(f, 0), out.triangles(f, 1));
    EXPECT_LT(out.triangles(f, 0), out.triangles(f, 2));
    if (f > 0) {
      EXPECT_TRUE(std::make_tuple(out.triangles(f - 1, 0), out.triangles(f - 1, 1),
                                  out.triangles(f - 1, 2)) <
                  std::make_tuple(out.triangles(f, 0), out.triangles(f, 1), out.triangles(f, 2)));
    }
  }
}

}  // namespace
}  // namespace acdplan::acd
