#pragma once
// Triangle meshes from files: OBJ, OFF, PLY and STL read by our own readers, in double
// precision (envs/obj_off_reader.h, envs/ply_reader.h, envs/stl_reader.h), the other formats
// through assimp.

#include <string>

#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Reads the mesh in `path` as one acd::TriangleMesh, polygons triangulated. By extension (any
/// case): .obj, .off, .ply and .stl with ReadObj(), ReadOff(), ReadPly() and ReadStl(), in
/// double precision; every other format assimp reads (COLLADA .dae, glTF .gltf/.glb, ...)
/// through assimp, in single precision, with node transforms applied and identical vertices
/// joined.
/// @throws InputError "<path>: cannot read the file: <reason>" when it cannot be opened,
///         "<path>:<line>: <rule>" for a malformed OBJ, OFF, PLY or STL file (a binary PLY's
///         or STL's element or facet instead of a line), "<path>: cannot read mesh:
///         <reason>" when assimp cannot parse it, and "<path>: no triangles in file".
acd::TriangleMesh ReadMesh(const std::string& path);

/// The extensions IsMeshFile() knows, for messages.
inline constexpr char kMeshFileExtensions[] =
    ".obj, .off, .ply, .stl, or a format assimp reads (.dae, .gltf, .glb, .fbx, .3ds, .3mf, .x3d, "
    ".blend, ...)";

/// Whether `path` names a mesh file by its extension (any case), the formats the loaders and
/// `acdplan decompose` take as meshes: .obj, .off, .ply, .stl, and every extension the assimp
/// library linked reads (Debian's 5.2: COLLADA .dae, glTF .gltf/.glb, FBX, 3DS, 3MF, X3D,
/// Blender, IFC, DXF, LightWave, ... about 70), but .prj, a shapefile's projection file.
bool IsMeshFile(const std::string& path);

}  // namespace acdplan::envs
