#pragma once
// Wavefront OBJ and Geomview OFF meshes read in double precision. Debian's assimp reads every
// coordinate as a single-precision float, which moves a georeferenced vertex near 4.5e6 by up
// to 0.25 m; these two text formats, the ones CGAL and most robotics tools write, are read
// here instead, to the digit.

#include <istream>
#include <string>

#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Reads the polygonal faces of an OBJ file: `v` lines (the first three numbers; colours after
/// them are skipped) and `f`/`fo` lines (corners "v", "v/vt", "v//vn", "v/vt/vn", 1-based, or
/// negative: relative to the vertices read so far). Faces of more than three corners are
/// triangulated by ear clipping in their best-fit plane, keeping their orientation. Lines
/// ending in '\' continue on the next. Points, lines, texture and material statements carry no
/// surface and are skipped; free-form surfaces (`surf`) are an error, as they would be lost.
/// Vertices no face uses are dropped, the others keep their order.
/// @param source Names the input in messages (the file's path).
/// @throws InputError "<source>:<line>: <rule>", e.g. "cup.obj:12: face refers to vertex 17,
///         but the file has 12 vertices", or "<source>: no triangles in file".
acd::TriangleMesh ReadObj(std::istream& in, const std::string& source);

/// Reads an OFF file: the header keyword (OFF, with Geomview's optional ST, C and N prefixes
/// whose extra per-vertex numbers are skipped; it may be left out), the vertex, face and edge
/// counts, the vertex lines (the first three numbers) and the face lines ("k i_1 ... i_k",
/// 0-based, a face colour after them skipped). Faces of more than three corners are
/// triangulated like ReadObj()'s; unused vertices are dropped. Comments run from '#' to the end
/// of a line. Anything after the declared faces is an error (a wrong count).
/// @throws InputError "<source>:<line>: <rule>", e.g. "t.off:2: expected the vertex, face and
///         edge counts, got 'x'".
acd::TriangleMesh ReadOff(std::istream& in, const std::string& source);

}  // namespace acdplan::envs
