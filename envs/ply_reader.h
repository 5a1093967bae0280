#pragma once
// PLY (Stanford polygon file) meshes read as stored. trimesh and Open3D write vertices as
// doubles by default; Debian's assimp would read them as single-precision floats, which moves a
// georeferenced vertex near 4.5e6 by up to 0.25 m, so PLY is read here instead.

#include <istream>
#include <string>

#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Reads a PLY file, ASCII or binary (either byte order): the properties x, y and z of the
/// element `vertex` (any of PLY's eight number types; a double stays a double, ASCII digits are
/// read as doubles whatever type the header declares) and the list property `vertex_indices`
/// (or `vertex_index`) of the element `face`, 0-based. Other elements and properties (normals,
/// colours, texture coordinates, edges, materials) carry no surface and are read past. Faces of
/// more than three corners are triangulated like ReadObj()'s; vertices no face uses are
/// dropped, the others keep their order. `in` must be opened in binary mode.
/// @param source Names the input in messages (the file's path).
/// @throws InputError "<source>:<line>: <rule>" for the header and ASCII data, e.g. "m.ply:3:
///         unknown property type 'real'", "m.ply:14: face refers to vertex 9, but the vertices
///         are 0 to 7"; "<source>: <element> <k>: <rule>" for binary data, e.g. "m.ply: face 4:
///         the file ends inside it"; "<source>: no triangles in file".
acd::TriangleMesh ReadPly(std::istream& in, const std::string& source);

}  // namespace acdplan::envs
