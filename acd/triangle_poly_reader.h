#pragma once
// Triangle's .poly format (J. R. Shewchuk's 2D mesh generator): a planar straight-line graph
// and hole points, read as the region Triangle meshes.

#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Whether `text`, a .poly file, is in Triangle's format rather than Lien's (ReadPoly() tells
/// them apart with it): its first line holding data is a header of 2 to 4 integers
/// ("<vertices> <dimension> [<attributes> [<boundary markers>]]"), where Lien's holds the chain
/// count alone, and the file's third word is not Lien's 'out' or 'in'.
bool IsTrianglePoly(const std::string& text);

/// Parses Triangle's .poly format, as Triangle (`triangle -p`) reads it:
///   <vertices> <dimension: 2> [<attributes> [<boundary markers: 0 or 1>]]
///   <vertex number> <x> <y> [attributes] [boundary marker]      (one line per vertex)
///   <segments> [<boundary markers: 0 or 1>]
///   <segment number> <endpoint> <endpoint> [boundary marker]    (one line per segment)
///   <holes>
///   <hole number> <x> <y>                                       (one line per hole)
///   [<regions>, then one line per region: its number, x, y, attribute, maximum area]
/// Vertices are numbered from 0 or 1, as the first one is; endpoints refer to those numbers.
/// Text after '#' is a comment; blank lines are skipped; fields beyond those read (attributes,
/// markers, regional attributes) are ignored, as is what follows the sections. A vertex count
/// of 0 means the vertices are in the .node file beside `source` (same name, extension .node,
/// the header and vertex lines above).
/// The region is what Triangle meshes without -c: what closed loops of segments enclose, less
/// the regions of the hole points (internal::RegionsOfSegmentGraph(): segments may cross, and
/// internal or dangling ones vanish), returned as polygons with holes (the polygons of the
/// file, to be prepared: PreparePolygon()).
/// @param source  the file's path, named in messages ("<source>:<line>: <rule>") and used to
///        find the .node file.
/// @throws InputError naming the file, the line and the rule: a malformed header or number, a
///         dimension other than 2 ("a 3D .poly is TetGen's"), a count out of range, a truncated
///         file, an endpoint that is no vertex, a hole point on a segment, a .node file that
///         cannot be read, or segments that enclose no region.
std::vector<Polygon2d> ReadTrianglePoly(const std::string& text, const std::string& source);

}  // namespace acdplan::acd
