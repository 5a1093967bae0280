#include "acd/internal/closed_shells.h"

#include <gtest/gtest.h>

#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {
namespace {

// Closed shells in one mesh, each a list of its faces.
struct Shells {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  std::vector<std::vector<int>> shells;

  // The box [lo, hi]^3, facing outward (or inward, as a cavity's shell faces). Its vertex at
  // (lo, lo, lo) comes first, and its top face is split along the diagonal over x = y.
  void AddCube(double lo, double hi, bool inward = false) {
    const int base = static_cast<int>(vertices.size());
    for (int k = 0; k < 8; ++k) {
      vertices.emplace_back(k & 1 ? hi : lo, k & 2 ? hi : lo, k & 4 ? hi : lo);
    }
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    AddShell(base, quads, inward);
  }

  // The tetrahedron of the given corners, its faces oriented consistently.
  void AddTetrahedron(const std::vector<Eigen::Vector3d>& corners) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), corners.begin(), corners.end());
    std::vector<int> shell;
    for (const Eigen::Vector3i& f : {Eigen::Vector3i(0, 2, 1), Eigen::Vector3i(0, 1, 3),
                                     Eigen::Vector3i(1, 2, 3), Eigen::Vector3i(2, 0, 3)}) {
      shell.push_back(static_cast<int>(faces.size()));
      faces.push_back(f + Eigen::Vector3i::Constant(base));
    }
    shells.push_back(shell);
  }

  TriangleMesh Mesh() const { return MakeTriangleMesh(vertices, faces); }

 private:
  void AddShell(int base, const int (&quads)[6][4], bool inward) {
    std::vector<int> shell;
    for (const auto& q : quads) {
      for (const Eigen::Vector3i& t :
           {Eigen::Vector3i(q[0], q[1], q[2]), Eigen::Vector3i(q[0], q[2], q[3])}) {
        const Eigen::Vector3i face = inward ? Eigen::Vector3i(t[0], t[2], t[1]) : t;
        shell.push_back(static_cast<int>(faces.size()));
        faces.push_back(face + Eigen::Vector3i::Constant(base));
      }
    }
    shells.push_back(shell);
  }
};

TEST(EnclosingShellsTest, NestedCubesListEveryShellAroundThem) {
  Shells s;
  s.AddCube(0, 8);    // 0
  s.AddCube(1, 5);    // 1, inside 0
  s.AddCube(2, 3);    // 2, inside 0 and 1
  s.AddCube(10, 11);  // 3, apart
  s.AddCube(6, 7);    // 4, inside 0 only
  const TriangleMesh mesh = s.Mesh();
  ASSERT_TRUE(VolumeSign(mesh, s.shells[0]) > 0);
  const std::vector<std::vector<int>> enclosing = EnclosingShells(mesh, s.shells);
  EXPECT_EQ(enclosing, (std::vector<std::vector<int>>{{}, {0}, {0, 1}, {}, {0}}));
}

TEST(EnclosingShellsTest, ARayThroughAnEdgeIsCastAgain) {
  // The inner cubes' first vertices lie below the outer top face's diagonal (x = y), so their
  // upward rays meet that edge; rays in other directions decide.
  Shells s;
  s.AddCube(0, 4);
  s.AddCube(1, 2);
  s.AddCube(2.5, 3);
  const std::vector<std::vector<int>> enclosing = EnclosingShells(s.Mesh(), s.shells);
  EXPECT_EQ(enclosing, (std::vector<std::vector<int>>{{}, {0}, {0}}));
}

TEST(EnclosingShellsTest, AShellFacingInwardEnclosesAsWell) {
  // A cavity's shell faces into the solid's material; nesting does not depend on which way.
  Shells s;
  s.AddCube(0, 4, /*inward=*/true);
  s.AddCube(1, 2);
  s.AddCube(1.5, 1.7, /*inward=*/true);
  const TriangleMesh mesh = s.Mesh();
  ASSERT_TRUE(VolumeSign(mesh, s.shells[0]) < 0);
  const std::vector<std::vector<int>> enclosing = EnclosingShells(mesh, s.shells);
  EXPECT_EQ(enclosing, (std::vector<std::vector<int>>{{}, {0}, {0, 1}}));
}

TEST(EnclosingShellsTest, AShellTouchingFromInsideIsTestedAtAVertexOffTheOther) {
  // The tetrahedron's first vertex lies on the cube's bottom face, its others inside.
  Shells s;
  s.AddCube(0, 4);
  s.AddTetrahedron({{2, 2, 0}, {3, 2, 1}, {2, 3, 1}, {2.5, 2.5, 2}});
  const std::vector<std::vector<int>> enclosing = EnclosingShells(s.Mesh(), s.shells);
  EXPECT_EQ(enclosing, (std::vector<std::vector<int>>{{}, {0}}));
}

}  // namespace
}  // namespace acdplan::acd::internal
