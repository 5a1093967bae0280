#pragma once
// Reads the polygons of one Well-Known Binary geometry (a GeoPackage's or PostGIS's storage).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// The polygons of one WKB geometry, as written (not yet cleaned or validated: see
/// PreparePolygon()).
struct WkbPolygons {
  std::vector<Polygon2d> polygons;
  /// Per polygon: the multi-surface (MultiPolygon, MultiSurface) of the geometry it is a member
  /// of, counted from 0 in the order written, or -1 for a lone Polygon (also one inside a
  /// GeometryCollection: a collection's members are not held to be disjoint).
  std::vector<int> multipolygons;
  /// The geometries without area that were passed over (Point, LineString, their multi and curve
  /// forms), by type name in the order first met, with how many of each.
  std::vector<std::pair<std::string, int>> non_areal;
  /// Rings written without their closing point (taken as they are).
  int unclosed_rings = 0;
};

/// Parses one geometry in Well-Known Binary: OGC Simple Features' (06-103r4, Sec. 8.2) with
/// ISO 13249-3's z / m type codes (1000 + t, 2000 + t, 3000 + t) and PostGIS's extended WKB
/// (the z, m and SRID flags of the type word; the SRID is skipped), each geometry in the byte
/// order its first byte names. Polygon, Triangle, MultiPolygon, GeometryCollection, and the
/// curve types where every ring is straight (a CurvePolygon whose rings are LineStrings, a
/// MultiSurface of such), to any nesting; z and m values are ignored; an empty polygon holds
/// none. A ring's closing point (it repeats the first) is dropped; an unclosed ring is taken as
/// it is and counted. Points and lines are passed over and listed (the caller decides whether
/// that is an error). Messages read "<where>: WKB byte <offset>: <rule>".
/// @throws InputError for a truncated or malformed geometry, a non-finite coordinate, a curved
///         ring (CircularString, CompoundCurve: linearize first), a polyhedral surface or TIN,
///         nesting deeper than 32, or bytes after the geometry.
WkbPolygons ReadWkb(const unsigned char* data, size_t size, const std::string& where);

}  // namespace acdplan::acd
