#pragma once
// An exact plane splitter for closed triangle meshes (the solid ACD's cut, Sec. V.B.3).
// Internal: include only from .cpp files of the acd library (it exposes CGAL's Epeck kernel).

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;

/// A closed, outward-oriented triangle mesh with exact (Epeck) vertices: one or more shells
/// (an outer shell and the cavity shells inside it). Each cut is exact: the guide's measurements
/// show double-rounded clip chains break after two levels of oblique cuts. The solid ACD rounds
/// a piece to doubles between cuts only after RoundsToValidSolid() accepts the rounding.
struct ExactPiece {
  std::vector<ExactKernel::Point_3> points;
  /// Each point rounded to doubles once, when it was made: a lazy exact number's
  /// approximation tightens whenever a predicate forces its exact value, so rounding later
  /// could give two pieces sharing a point two different doubles.
  std::vector<Eigen::Vector3d> rounded;
  std::vector<std::array<int, 3>> triangles;  ///< Counter-clockwise seen from outside.
};

/// The exact copy of `mesh`.
ExactPiece ToExact(const TriangleMesh& mesh);

/// `piece` with its rounded coordinates.
TriangleMesh ToDouble(const ExactPiece& piece);

/// The two closed halves of `piece` on either side of `plane`: `below` is the part on the
/// negative side, `above` the part on the positive side; either may be empty. Vertices are
/// classified with exact oriented_side, except that a vertex within kInPlaneTolerance of the
/// piece's size of the plane counts as on it (no rounding-level slivers; no vertex moves, so the
/// section is planar to within that tolerance); crossing edges are split at their exact
/// intersection points; faces lying in the plane go to the side their solid lies on. The section
/// (one polygon with holes per loop nesting) is triangulated once by a constrained Delaunay
/// triangulation in the plane and given to both halves, reversed for `above`, so the halves
/// share an identical interface. O(n log n) for n triangles.
///
/// Returns false, with both halves empty, when the plane touches the surface inside the section
/// without crossing it: a vertex or an edge on the plane, off the section's border, lies in the
/// section or on its border (the bottom of a dimple or a groove the plane is tangent to). The cap
/// would pass through it, or within the tolerance of it, and leave a piece touching itself
/// there, which no later cut near that point can split into pieces that stay valid once rounded
/// (measured: hips at tau_rel 0.02, a piece left at 24 x tau). A plane moved off it cuts cleanly.
bool SplitByPlane(const ExactPiece& piece, const ExactKernel::Plane_3& plane, ExactPiece* below,
                  ExactPiece* above);

/// The connected solids of `piece`: its shells grouped by edge connectivity, each cavity shell
/// (negative volume) given to the smallest outer shell that contains it (EnclosingShells(), on
/// the rounded coordinates: exact); a cavity no outer shell contains stands alone, inside out,
/// and the caller rejects it. Ordered by their
/// smallest triangle index, so the order is deterministic.
std::vector<ExactPiece> ConnectedSolids(const ExactPiece& piece);

/// The faces of a piece, each known by its three rounded corners in any order: built once per
/// cut piece, asked about the faces of each of its children. O(n log n) for n triangles.
class RoundedFaceSet {
 public:
  explicit RoundedFaceSet(const ExactPiece& piece);
  /// Whether the set has a face with the rounded corners of triangle `t` of `piece`.
  bool Contains(const ExactPiece& piece, const std::array<int, 3>& t) const;

 private:
  using Key = std::array<double, 9>;  // the corners, sorted
  static Key KeyOf(const ExactPiece& piece, const std::array<int, 3>& t);
  std::vector<Key> keys_;  // sorted
};

/// Whether `piece` rounded to doubles (ToDouble) is still the boundary of a solid, judged as
/// CheckDecomposition3d judges a component: vertices merged by rounded position, no triangle
/// with two corners at one position, a 2-manifold CGAL accepts, free of self-intersections
/// (exact predicates on the doubles). Exact cut points closer than a double's resolution
/// (two crossings on a sliver triangle's edges 1e-18 apart) round onto one position, and
/// rounding can fold near-coplanar faces through each other; a cut whose pieces do not round
/// cleanly is rejected rather than output. O(n log n) for n triangles.
///
/// With `valid_source`, the faces of a piece that rounds to a valid solid and that `piece` was
/// cut from, two faces that it has too are known not to cross, and only pairs with a fresh face
/// (a cut or cap face) are tested.
bool RoundsToValidSolid(const ExactPiece& piece, const RoundedFaceSet* valid_source = nullptr);

/// Whether every edge of `triangles` has exactly two faces, which run along it in opposite
/// directions (closed, edge-manifold, consistently oriented).
bool IsClosedSurface(const std::vector<std::array<int, 3>>& triangles);

/// Shells of `triangles` (edge-connected triangle sets), the sum of their genera,
/// (2 - V + E - F) / 2 per shell, and IsClosedSurface(): all from one sorted list of edges.
struct ShellTopology {
  int shells = 0;
  int genus = 0;
  bool closed = false;
};
ShellTopology Topology(const std::vector<std::array<int, 3>>& triangles);

}  // namespace acdplan::acd::internal
