#pragma once
// The cut plane that resolves a piece's most concave feature (dissertation Sec. V.B.3).

#include <array>
#include <optional>
#include <tuple>
#include <vector>

#include "acd/decomposition3d.h"
#include "acd/internal/solid_concavity.h"
#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// Vertices of a mesh in one plane, and the coordinate axis the plane is seen along one to one.
struct VerticesInPlane {
  int axis = 0;
  std::vector<int> vertices;
};

/// A candidate plane with its score: the worse side's estimated concavity [units] and the sum of
/// the two sides' hull volumes.
struct ScoredPlane {
  Plane3d plane;
  double concavity = 0.0;
  double hull_volume = 0.0;
};

/// The world's x, y and z axes.
std::array<Eigen::Vector3d, 3> WorldAxes();

/// The directions of a part's axis-aligned candidate planes: the world's axes, unless three
/// orthogonal directions of the part's own carry more of its area in faces facing along them
/// (a model with flat faces, turned off the world's axes; else the world's axes keep the
/// modeller's up). The directions are found among the normals of the part's largest faces:
/// the first carries the most area, the second the most of those orthogonal to it. Turns
/// with the part, except where directions tie. O(F) for F faces.
std::array<Eigen::Vector3d, 3> PartAxes(const TriangleMesh& part);

/// Candidate cut planes through the witness of `concavity`, best first. Candidates:
///  - the planes of the faces at the witness (extending a notch's walls, as the 2D Resolve
///    extends an edge of the notch);
///  - with `feature_grouping`, the plane best fitting the global cut (FindGlobalCut(),
///    Sec. V.B.2-3), and the plane parallel to it through the witness. After the walls, so
///    that they win ties: on a coarse block the edge-graph cycle crosses big faces on their
///    diagonals (an L-block's would cut it on the diagonal, an opening of area sqrt(2) where
///    its wall extended gives 1, both convex);
///  - the three planes through the witness along `axes` (PartAxes());
///  - the principal planes of the witness's pocket (the PCA fit of Eq. 5.3 and the two
///    planes across it, which cut a pocket's walls or a handle open, Sec. V.C);
///  - the bisectors of the dihedral angles at the witness's edges.
/// Each is scored without building meshes (the guide's cheap scoring): the vertices of each
/// side plus the points where edges cross the plane are hulled (of the crossing points, and of
/// the vertices in one of `caps`, only their polygon's corners: the others are no hull vertices
/// but cost convex_hull_3 exact tests, being in the plane of a hull facet), and a side's
/// concavity is estimated as the largest distance of its vertices and of the section's points
/// to its hull's planes other than the cut's own (the cap is surface, not a bridge). Ranked
/// by that estimate of the worse side, in bins of tau / 4 above tau (all sides within tau are
/// equal), then by the sum of the two hulls' volumes, then by the order above. Planes that
/// leave a side without a vertex strictly on it are dropped.
///
/// Scored lazily: each candidate's side with more vertices first, and its other side only when
/// the first cannot rank it after the plane Next() is about to return (a side's bin and hull
/// volume bound the candidate's from below). The order is the same as with both sides scored
/// up front (`lazy` false, for tests). A piece is usually cut by its first plane; on teddy
/// (tau_rel 0.05) 22% of the sides are then never hulled. O(C V log V) for C candidates.
class CutPlaneRanking {
 public:
  /// `caps`: the planes of the cuts that made the piece (its caps lie in them).
  CutPlaneRanking(const TriangleMesh& mesh, const SolidConcavity& concavity, double tau,
                  const std::vector<Plane3d>& caps, bool feature_grouping = false, bool lazy = true,
                  const std::array<Eigen::Vector3d, 3>& axes = WorldAxes());
  /// The next plane in rank order; none once every candidate is returned or dropped.
  std::optional<ScoredPlane> Next();
  /// How many sides (of two per candidate) were hulled so far.
  int SidesScored() const;

 private:
  struct Candidate {
    Plane3d plane;
    int sides_scored = 0;      // 0, 1 or 2
    int first_side = -1;       // the side scored first: -1 below the plane, 1 above
    bool done = false;         // returned or dropped
    double concavity = 0.0;    // the worse scored side's
    double hull_volume = 0.0;  // summed over the scored sides
  };
  void ScoreNextSide(Candidate* candidate);
  // (bin, rounded hull volume, index) of candidate `c`: its rank key once both sides are
  // scored, a lower bound of it after one.
  std::tuple<long long, long long, size_t> KeyOf(size_t c) const;

  const TriangleMesh& mesh_;
  double tau_, bin_, volume_unit_, tol_;
  std::vector<VerticesInPlane> caps_;
  std::vector<Candidate> candidates_;
};

}  // namespace acdplan::acd::internal
