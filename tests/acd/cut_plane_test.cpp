#include "acd/internal/cut_plane.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "acd/mesh_measures.h"
#include "solid_test_meshes.h"
#include "tests/data_paths.h"

namespace acdplan::acd::internal {
namespace {

struct Ranked {
  std::vector<ScoredPlane> planes;
  int sides_scored = 0;
};

Ranked Rank(const TriangleMesh& mesh, double tau, bool lazy,
            const std::vector<Plane3d>& caps = {}) {
  const SolidConcavity concavity = MeasureSolidConcavity(mesh, tau);
  CutPlaneRanking ranking(mesh, concavity, tau, caps, /*feature_grouping=*/true, lazy);
  Ranked out;
  while (const std::optional<ScoredPlane> next = ranking.Next()) out.planes.push_back(*next);
  out.sides_scored = ranking.SidesScored();
  return out;
}

void ExpectSameRanking(const Ranked& a, const Ranked& b, const std::string& what) {
  ASSERT_EQ(a.planes.size(), b.planes.size()) << what;
  for (size_t i = 0; i < a.planes.size(); ++i) {
    EXPECT_EQ(a.planes[i].plane.normal, b.planes[i].plane.normal) << what << " " << i;
    EXPECT_EQ(a.planes[i].plane.offset, b.planes[i].plane.offset) << what << " " << i;
    EXPECT_EQ(a.planes[i].concavity, b.planes[i].concavity) << what << " " << i;
    EXPECT_EQ(a.planes[i].hull_volume, b.planes[i].hull_volume) << what << " " << i;
  }
}

// `mesh` with each triangle in the plane z = `z` split at its centroid, `rounds` times: a flat
// cap with vertices inside it (exactly in the plane, as z is).
TriangleMesh SplitFacesAt(const TriangleMesh& mesh, double z, int rounds) {
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    vertices.emplace_back(mesh.vertices.row(i));
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f)
    faces.emplace_back(mesh.triangles.row(f));
  for (int round = 0; round < rounds; ++round) {
    std::vector<Eigen::Vector3i> next;
    for (const Eigen::Vector3i& t : faces) {
      const Eigen::Vector3d &a = vertices[static_cast<size_t>(t(0))],
                            &b = vertices[static_cast<size_t>(t(1))],
                            &c = vertices[static_cast<size_t>(t(2))];
      if (a.z() != z || b.z() != z || c.z() != z) {
        next.push_back(t);
        continue;
      }
      const int m = static_cast<int>(vertices.size());
      vertices.push_back((a + b + c) / 3);
      next.emplace_back(t(0), t(1), m);
      next.emplace_back(t(1), t(2), m);
      next.emplace_back(t(2), t(0), m);
    }
    faces = std::move(next);
  }
  return MakeTriangleMesh(vertices, faces);
}

TriangleMesh Load(const std::string& name) {
  TriangleMesh mesh =
      test::ReadObjForTest(acdplan::test::DataDir() + "/meshes/vhacd/" + name + ".obj");
  if (MeshVolume(mesh) < 0) mesh.triangles.col(1).swap(mesh.triangles.col(2));
  return mesh;
}

// Whether `a` and `b` hold the same three directions, in any order and sign.
bool SameAxes(const std::array<Eigen::Vector3d, 3>& a, const std::array<Eigen::Vector3d, 3>& b) {
  for (const Eigen::Vector3d& u : a) {
    bool found = false;
    for (const Eigen::Vector3d& v : b) found = found || std::abs(u.dot(v)) > 1 - 1e-9;
    if (!found) return false;
  }
  return true;
}

// The U-block's own axes are the world's; turned, its axes turn with it. A torus faces no three
// directions with much area: it keeps the world's.
TEST(PartAxes, TurnWithAModelsFlatFaces) {
  const std::array<Eigen::Vector3d, 3> world = WorldAxes();
  const TriangleMesh u = test::UBlock();
  const std::array<Eigen::Vector3d, 3> own = PartAxes(u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(own[static_cast<size_t>(k)], world[static_cast<size_t>(k)]);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  TriangleMesh turned = u;
  for (Eigen::Index i = 0; i < turned.vertices.rows(); ++i) {
    turned.vertices.row(i) = (r * u.vertices.row(i).transpose()).transpose();
  }
  EXPECT_TRUE(SameAxes(PartAxes(turned), {r.col(0), r.col(1), r.col(2)}));
  EXPECT_TRUE(SameAxes(PartAxes(test::Torus(2.0, 1.0, 16, 8)), world));
}

// The U-block's slot floor extended (y = 1) leaves the base and two posts, all convex; every
// other candidate leaves an L-shaped side, 1 deep.
TEST(CutPlaneRanking, RanksTheUBlockSlotFloorFirst) {
  const Ranked ranked = Rank(test::UBlock(), 0.1, true);
  ASSERT_FALSE(ranked.planes.empty());
  EXPECT_NEAR(ranked.planes.front().plane.normal.y(), 1.0, 1e-12);
  EXPECT_NEAR(ranked.planes.front().plane.offset, 1.0, 1e-12);
  EXPECT_LE(ranked.planes.front().concavity, 0.1);
}

// The torus is deepest on its tube's inner equator, a ring of vertices 0.5 under the bridge over
// its hole. A cut along that ring leaves the depth on both halves, and the ranking must say so:
// the cap the cut makes is surface, not a bridge. Counted as one, it hid the ring and all but
// the next ring's 0.25, and such cuts won (torus2 in the corpus fell into 204 washers).
TEST(CutPlaneRanking, ACutAlongTheDeepestRingKeepsItsDepth) {
  const Ranked ranked = Rank(test::Torus(2.0, 0.5, 24, 12), 0.05, false);
  int found = 0;
  for (const ScoredPlane& p : ranked.planes) {
    if (std::abs(std::abs(p.plane.normal.z()) - 1) > 1e-12 || std::abs(p.plane.offset) > 1e-9) {
      continue;
    }
    ++found;
    EXPECT_NEAR(p.concavity, 0.5, 1e-9);
  }
  EXPECT_EQ(found, 1);
}

// A candidate's second side is scored only when its first cannot rank it last; the order must
// be the one with every side scored.
TEST(CutPlaneRanking, LazyScoringKeepsTheOrder) {
  struct Case {
    std::string name;
    TriangleMesh mesh;
  };
  const std::vector<Case> cases = {{"L-block", test::LBlock()},
                                   {"U-block", test::UBlock()},
                                   {"torus", test::Torus(2.0, 0.5, 24, 12)},
                                   {"torus1", Load("torus1")},
                                   {"hose", Load("hose")},
                                   {"cup", Load("cup")}};
  for (const Case& c : cases) {
    ASSERT_GT(c.mesh.triangles.rows(), 0) << c.name;
    for (const double tau_rel : {0.2, 0.02}) {
      const double tau = tau_rel * ReferenceRadius(c.mesh);
      const Ranked lazy = Rank(c.mesh, tau, true), eager = Rank(c.mesh, tau, false);
      ExpectSameRanking(lazy, eager, c.name + " " + std::to_string(tau_rel));
      EXPECT_FALSE(lazy.planes.empty()) << c.name << " " << tau_rel;
      // Draining the ranking scores every candidate fully, lazily or not.
      EXPECT_EQ(lazy.sides_scored, eager.sides_scored) << c.name;
    }
  }
}

// Taking only the first plane, as a cut that succeeds does, leaves second sides unscored.
TEST(CutPlaneRanking, TheFirstPlaneNeedsFewerSides) {
  const TriangleMesh mesh = Load("cup");
  ASSERT_GT(mesh.triangles.rows(), 0);
  const double tau = 0.02 * ReferenceRadius(mesh);
  const SolidConcavity concavity = MeasureSolidConcavity(mesh, tau);
  CutPlaneRanking lazy(mesh, concavity, tau, {}, true, true),
      eager(mesh, concavity, tau, {}, true, false);
  const std::optional<ScoredPlane> a = lazy.Next(), b = eager.Next();
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->plane.normal, b->plane.normal);
  EXPECT_EQ(a->plane.offset, b->plane.offset);
  EXPECT_LT(lazy.SidesScored(), eager.SidesScored());
}

// Vertices inside a cap are no hull vertices: hulling only the cap's corners scores every
// candidate the same, to the bit, on a U-block whose top is split into 54 triangles.
TEST(CutPlaneRanking, CapCornersScoreAsTheWholeCap) {
  const TriangleMesh mesh = SplitFacesAt(test::UBlock(), 1.0, 2);
  ASSERT_GT(mesh.vertices.rows(), test::UBlock().vertices.rows() + 20);
  const Plane3d top{Eigen::Vector3d::UnitZ(), 1.0};
  for (const double tau : {0.1, 0.5}) {
    const Ranked plain = Rank(mesh, tau, false), capped = Rank(mesh, tau, false, {top});
    ASSERT_FALSE(plain.planes.empty());
    ExpectSameRanking(plain, capped, "tau " + std::to_string(tau));
  }
}

}  // namespace
}  // namespace acdplan::acd::internal
