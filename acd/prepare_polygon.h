#pragma once
// Validation and cleaning of raw polygons before decomposition.

#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Largest |coordinate| PreparePolygons() and RepairPolygon() accept. The measures of a polygon
/// multiply coordinate differences: areas and squared distances square them, the centroid's
/// first moments and a crossing point's construction cube them. Beyond 1e100 a difference is up
/// to 2e100 and its cube 8e300, so a ring's moment sum would overflow a double (1.8e308) and
/// centroids, then areas and distances, turn into inf or NaN (a vertex at 5e185 did). Such
/// coordinates carry no geometry a double computation can measure, so they are rejected.
inline constexpr double kMaxCoordinate = 1e100;

/// Throws InputError (naming `where`, the ring and the vertex) unless every coordinate of
/// `raw` is finite and at most kMaxCoordinate in magnitude: the first check of
/// PreparePolygons() and RepairPolygon(), as no repair brings a coordinate into range.
void CheckCoordinates(const Polygon2d& raw, const std::string& where);

/// Validates `raw` and returns its cleaned form as polygons that satisfy Polygon2d's
/// invariants (simple rings, holes strictly inside and pairwise disjoint), whose union is
/// `raw`'s interior. One polygon, unchanged but for cleaning, unless rings touch.
///
/// Cleans what is valid but untidy: re-orients rings (outer counter-clockwise, holes
/// clockwise), drops consecutive duplicate vertices (and a repeated closing vertex), drops
/// collinear vertices and zero-width spikes.
///
/// Accepted touchings (OGC Simple Features validity, plus self-tangent "inverted" rings as
/// ESRI writes them): rings may meet at isolated points: a hole's vertex on the outer ring or
/// on another hole (at a vertex or inside an edge), two holes sharing a vertex, a ring touching
/// itself at a vertex (an outer ring pinching off a pocket of the exterior, or two lobes of
/// one ring meeting at a point). Such a polygon is returned as several polygons: each part of
/// the interior that only meets the rest at points becomes its own polygon (two lobes: two
/// polygons), and each part whose boundary passes a point twice (a pinch) is cut along
/// diagonals of a constrained Delaunay triangulation into polygons whose rings are simple and
/// disjoint (grown triangle by triangle while each vertex keeps one fan of triangles, then
/// joined again across the cuts wherever the union keeps one fan at every vertex: a pinch costs
/// a few pieces, and the holes away from their cuts stay holes; a part without pinches stays
/// whole). Decompose2d() of the pieces reports openings across the cuts.
///
/// Still rejected (InputError), checked in this order: a non-finite coordinate, or one of
/// magnitude above 1e100 (products of coordinates would overflow a double); a ring with
/// fewer than 3 distinct, non-collinear vertices or zero area; a ring crossing itself, or
/// overlapping itself along a segment ("is not simple"); a hole crossing or overlapping the
/// outer ring ("touches or crosses the outer ring", the strict rule's wording); a hole outside
/// the outer ring; two holes crossing or overlapping; nested holes; rings meeting at a shared
/// vertex where they cross there ("outer ring crosses itself at the shared vertex (x, y)",
/// "hole 0 and hole 1 cross at ..."); a hole that, with the rings it touches, closes a chain
/// around part of the interior ("hole k disconnects the interior": the interior must stay
/// connected; touching at two points of the outer ring is such a chain).
///
/// Messages name rings as "outer ring" or "hole k" (k the 0-based index in `raw.holes`) and
/// vertices by their 0-based index in the ring as given in `raw` (for a .poly file: after its
/// vertex order is applied), e.g. "monkey.poly: polygon 0: outer ring is not simple: edges
/// (3,4) and (7,8) intersect at (0.5, 1.25)". Where several pairs intersect, the pair that
/// comes first in the cleaned ring's order is named.
///
/// Complexity: O(n log n) for n vertices in all when no rings meet (CGAL's surface sweep, a
/// Bentley-Ottmann variant, stopping at the first intersection) plus O(h * m) point-in-ring
/// tests for h holes of m vertices. When rings meet: O(n log n + k) intersection searches over
/// the k edge pairs whose x-ranges overlap, O(h * m + h^2) containment tests (bounding boxes
/// filter the h^2), and an O(n log n) constrained triangulation with linear passes over it.
/// All predicates are exact (CGAL's Epick kernel; the triangulation needs no constructions,
/// since touching rings only meet at input vertices; ring orientation by the exact area sign);
/// the sweep, which orders constructed crossing points, runs on Epeck (exact constructions).
/// Naming the offending edges after a failure can take O(n^2) in the worst case.
///
/// @param where  names the element in messages, e.g. "monkey.poly: polygon 0".
/// @throws InputError, one message naming `where`, the ring and the rule, as listed above.
std::vector<Polygon2d> PreparePolygons(const Polygon2d& raw, const std::string& where);

/// PreparePolygons() for callers that need exactly one polygon (a robot outline).
/// @throws InputError as PreparePolygons(), and when touching rings make `raw` several
///         polygons ("<where>: rings touch at points, which makes the polygon N polygons where
///         one is required ...").
Polygon2d PreparePolygon(const Polygon2d& raw, const std::string& where);

}  // namespace acdplan::acd
