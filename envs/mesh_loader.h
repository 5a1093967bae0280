#pragma once
// Triangle meshes from files, through assimp.

#include <string>

#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Reads every mesh of the scene in `path` (OBJ, STL, PLY, OFF, COLLADA .dae, glTF .gltf/.glb
/// and the other formats assimp reads), with node transforms applied, polygons triangulated
/// and identical vertices joined, as one acd::TriangleMesh.
/// @throws InputError "<path>: cannot read mesh: <reason>" when the file is missing or
///         assimp cannot parse it, and "<path>: no triangles in file" when it holds none.
acd::TriangleMesh ReadMesh(const std::string& path);

}  // namespace acdplan::envs
