#pragma once
// Concavity of a polygon with holes (dissertation Ch. III.B, Ch. IV.A).

#include <vector>

#include "acd/concavity_measure.h"
#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Options for MeasureConcavity(); `{}` is valid.
struct ConcavityOptions {
  ConcavityMeasure measure = ConcavityMeasure::kShortestPath;
  HoleDiameter hole_diameter = HoleDiameter::kAuto;
  double tau = 0.0;  ///< Only H2 uses it (Algorithm 4 switches to SP when SL <= tau).
};

/// The antipodal pair of a hole and its concavity (Eqn. 4.2).
struct HoleConcavity {
  int p = 0;               ///< Hole vertex to connect to the outer boundary first.
  int cw_p = 0;            ///< Its antipode cw(p).
  double diameter = 0.0;   ///< dist(p, cw(p)) [units]: Euclidean or geodesic.
  double depth = 0.0;      ///< concavity(x) + dist(x, p): how deep the hole sits [units].
  double concavity = 0.0;  ///< depth + diameter + delta, delta = outer concavity (Eqn. 4.2).
};

/// Concavity of a polygon: per outer vertex, per hole, and the maximum with its witness.
struct Concavity2d {
  std::vector<double> outer;  ///< Per outer-ring vertex [units]; 0 on the convex hull.
  std::vector<int> hull;      ///< ConvexHullIndices() of the outer ring.
  /// Per hull edge k, from hull[k] to hull[k + 1] (cyclically): the largest concavity of the
  /// outer vertices strictly between its ends (its pockets' depth), or -infinity if none.
  std::vector<double> bridge_max;
  std::vector<HoleConcavity> holes;  ///< Per hole.
  double value = 0.0;                ///< Max over notches and holes; 0 iff the polygon is convex.
  int witness_hole = -1;             ///< Hole holding the maximum, or -1 for the outer ring.
  int witness_vertex = -1;           ///< Outer vertex (a notch) holding the maximum, or -1.
};

/// Measures the concavity of `polygon` (prepared: outer CCW, holes CW). A notch is a vertex
/// whose interior angle exceeds 180 degrees by more than rounding noise (see IsNotch()); the
/// maximum is only taken over notches (Lemma C.2), so `value` is 0 exactly when no notch and no
/// hole exists (Lemma C.3). O(n) per pocket for SL; SP adds a triangulation per pocket.
Concavity2d MeasureConcavity(const Polygon2d& polygon, const ConcavityOptions& options = {});

/// True when the turn prev -> v -> next is clockwise (an interior angle above 180 degrees for a
/// counter-clockwise boundary, or for a clockwise hole seen from the polygon) by more than
/// rounding noise: the exact orientation is negative and v lies farther than 1e-13 times the
/// largest coordinate magnitude from the line through prev and next. The noise floor keeps a
/// vertex created on an edge (a cut ending there) from counting as a notch.
bool IsNotch(const Point2d& prev, const Point2d& v, const Point2d& next);

/// Number of notches over all rings of `polygon`.
int CountNotches(const Polygon2d& polygon);

/// Ring indices of the convex hull vertices of a simple counter-clockwise ring, in increasing
/// order (the ring order is the hull's order). Hull vertices are strictly convex; ring vertices
/// lying on a hull edge are not included.
std::vector<int> ConvexHullIndices(const Ring2d& ring);

/// Convex hull of `points` (any order), counter-clockwise, without collinear vertices.
Ring2d ConvexHull(const Ring2d& points);

}  // namespace acdplan::acd
