#pragma once
// Concavity of a closed polyhedron (dissertation Sec. V.B.1): pockets, bridges, and the depth
// of each pocket point below its bridge.

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// The measure of one piece and where it is deepest.
struct SolidConcavity {
  double value = 0.0;                                 ///< Largest depth [units]; 0 if convex.
  Eigen::Vector3d witness = Eigen::Vector3d::Zero();  ///< The most concave point.
  int witness_vertex = -1;                            ///< Its vertex, or -1 when a face sample won.
  int witness_face = -1;          ///< A pocket face at the witness (-1 if convex).
  std::vector<int> pocket_faces;  ///< The faces of the witness's pocket.
  int witness_pocket = -1;        ///< The witness's pocket: an index into the ids below.
  /// Per face: its pocket (0, 1, ... in order of their smallest face), or -1 on the hull.
  std::vector<int> face_pocket;
  /// Per vertex: its measured depth [units], the largest over the pockets it borders; 0 for a
  /// vertex of hull faces only. Feature grouping reads pocket borders in this space (Eq. 5.1).
  std::vector<double> vertex_concavity;
  TriangleMesh hull;  ///< The convex hull of the piece.
  double hull_volume = 0.0;
};

/// Measures `mesh` (closed, outward) against its convex hull:
///  - a piece within kInPlaneTolerance of its size of one hull plane is flat: value 0;
///  - faces whose three vertices lie in one hull plane are on the hull; the others, grouped by
///    shared edges, are pockets (Fig. 37);
///  - a hull plane is a bridge plane unless the surface faces lying in it cover its hull
///    facet; a pocket's bridge is the set of bridge planes its border vertices span (three
///    border vertices in the plane, not collinear), so a slot beside a wall is measured from
///    its rim, not from the wall (the guide's all-hull-planes lower bound misses that);
///  - bridge planes are clustered into patches (Algorithm 6, epsilon = tau / 2): a plane
///    whose border vertices lie within epsilon of a patch's plane is measured as that plane;
///  - the depth of a pocket point is its distance to the nearest bridge plane it faces (its
///    face's or vertex's outward normal has a positive component along the plane's normal:
///    Lien projects a pocket point onto the bridge above it, so a lid its wall meets at a right
///    angle does not count), or to the nearest bridge plane if it faces none; this is a lower
///    bound of the distance to the bridge surface that equals it for a planar bridge; a
///    pocket without a bridge (a cavity shell) is measured against every hull plane;
///  - points are the pocket vertices plus deterministic face samples (centroids and a
///    barycentric grid spaced <= tau), because the depth is concave over a face and its
///    maximum may lie inside one; the witness is the deepest vertex unless a sample is deeper
///    by more than kInPlaneTolerance of the mesh's size (the value is the deepest point's).
/// O((V + S) P) for V vertices, S samples and P hull planes.
SolidConcavity MeasureSolidConcavity(const TriangleMesh& mesh, double tau);

}  // namespace acdplan::acd::internal
