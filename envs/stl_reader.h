#pragma once
// STL meshes, the format CAD tools and robot descriptions (URDF) use most, read by our own
// reader: ASCII STL keeps every digit (assimp would round it to single precision), and both
// forms get errors that name the line or the facet.

#include <istream>
#include <string>

#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Reads an STL file, ASCII or binary. Binary: an 80-byte header, a little-endian facet count,
/// 50 bytes per facet (a normal, three corners as floats, an attribute word); a file is taken
/// as binary unless it starts with "solid" (as some CAD tools' binary headers do too) and is
/// text (no control characters but white space) and its size is not what a binary count says.
/// ASCII: `solid`, then `facet normal nx ny nz`, `outer loop`, three or more `vertex x y z`
/// lines, `endloop`, `endfacet`, ..., `endsolid`; several solids may follow each other. Facet
/// normals are ignored (the corners' order gives the orientation, as the format says). Corners
/// at identical positions (exact comparison) become one vertex, numbered in order of first use.
/// @param source Names the input in messages (the file's path).
/// @throws InputError "<source>:<line>: <rule>" for ASCII, e.g. "part.stl:7: expected
///         'endloop', got 'vertex'"; "<source>: facet <k>: <rule>" for binary, e.g. "part.stl:
///         facet 3: a corner is not finite"; "<source>: <rule>" for a binary file's size, e.g.
///         "part.stl: binary STL of 12 facets needs 684 bytes, the file has 600"; "<source>: no
///         triangles in file".
acd::TriangleMesh ReadStl(std::istream& in, const std::string& source);

}  // namespace acdplan::envs
