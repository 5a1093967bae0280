#pragma once
// Making invalid polygons valid, the way GEOS / PostGIS ST_MakeValid do with the even-odd rule.

#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// What RepairPolygon() made of a polygon.
struct RepairedPolygon {
  std::vector<Polygon2d> polygons;   ///< Valid and prepared (PreparePolygons()); may be empty.
  std::vector<std::string> changes;  ///< One line per change, "<where>: repaired: ..."; empty
                                     ///< when `raw` was valid.
};

/// Returns `raw` made valid. A valid `raw` comes back as PreparePolygons() returns it, with no
/// change. Otherwise:
///  1. each ring that cleans to fewer than 3 distinct, non-collinear vertices (e.g. a hole with
///     two vertices) is dropped: "hole 2 has 2 distinct, non-collinear vertices: dropped";
///  2. a ring given more than once is taken once: a ring that runs around the same vertices
///     k times ("hole 1 runs around its first 4 distinct vertices 2 times: taken once"), a hole
///     with the vertices of an earlier one in the same cyclic order, either way round ("hole 3
///     repeats hole 0: dropped");
///  3. if the rest is still invalid, the rings' even-odd region (internal::EvenOddRegions():
///     an exact arrangement of all ring edges; a face is inside when an odd number of ring
///     edges separates it from the unbounded face: a bow tie gives its two triangles, a hole
///     crossing the outer ring gives the symmetric difference, a spike out and back adds
///     nothing) is returned as polygons with holes: "<the rule broken>: rebuilt by the even-odd
///     rule into N polygon(s) with H hole(s), area A";
///  4. the result goes through PreparePolygons() (points where parts touch are handled there).
/// Where no two ring edges overlap, the area is GEOS's make-valid's ("linework", GEOS 3.11:
/// 4,500 random self-crossing polygons with crossing holes, all equal to 1e-9); where edges
/// overlap, GEOS merges them before it builds faces and keeps area that the even-odd rule
/// leaves out: what a spike closes off, and a hole that shares part of an edge with the outer
/// ring (kept filled).
/// Crossing points are rounded to doubles at the end; a rounding that makes rings cross is
/// reported as an InputError ("repair failed: ..."), not hidden.
/// O((n + k) log n) for n edges crossing k times, plus PreparePolygons().
/// @param where  names the polygon in messages and change lines, e.g. "tile.wkt: polygon 0".
/// @throws InputError if a coordinate is not finite or beyond kMaxCoordinate
///         (acd/prepare_polygon.h), with PreparePolygons()' message, or if the repaired result
///         cannot be represented in doubles.
RepairedPolygon RepairPolygon(const Polygon2d& raw, const std::string& where);

}  // namespace acdplan::acd
