#include "envs/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"
#include "envs/internal/file_extension.h"
#include "envs/obj_off_reader.h"
#include "envs/ply_reader.h"
#include "envs/stl_reader.h"

namespace acdplan::envs {

using internal::LowerExtension;

bool IsMeshFile(const std::string& path) {
  const std::string extension = LowerExtension(path);
  // A shapefile's projection file, though assimp lists the extension too.
  if (extension.empty() || extension == ".prj") return false;
  for (const char* own : {".obj", ".off", ".ply", ".stl"}) {
    if (extension == own) return true;
  }
  return Assimp::Importer().IsExtensionSupported(extension);
}

acd::TriangleMesh ReadMesh(const std::string& path) {
  if (const std::string reason = UnreadableFileReason(path); !reason.empty()) {
    throw InputError(path + ": cannot read the file: " + reason);
  }
  const std::string extension = LowerExtension(path);
  if (extension == ".obj" || extension == ".off" || extension == ".ply" || extension == ".stl") {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot read the file: " + std::strerror(errno));
    if (extension == ".ply") return ReadPly(in, path);
    if (extension == ".stl") return ReadStl(in, path);
    return extension == ".obj" ? ReadObj(in, path) : ReadOff(in, path);
  }
  Assimp::Importer importer;
  // Points and lines are not surfaces: drop them instead of failing on mixed files.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "unsupported or malformed file";
    throw InputError(path + ": cannot read mesh: " + reason);
  }
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const int base = static_cast<int>(vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        // Also a finite number in the file beyond float's range: assimp reads in float.
        throw InputError(path + ": mesh " + std::to_string(m) + ", vertex " + std::to_string(v) +
                         ": a coordinate is not finite as read (NaN or infinite, or beyond "
                         "3.4e38, the range of the single-precision floats assimp reads)");
      }
      vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      triangles.emplace_back(base + static_cast<int>(face.mIndices[0]),
                             base + static_cast<int>(face.mIndices[1]),
                             base + static_cast<int>(face.mIndices[2]));
    }
  }
  if (triangles.empty()) throw InputError(path + ": no triangles in file");
  acd::TriangleMesh result;
  result.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  result.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i) result.vertices.row(i) = vertices[i].transpose();
  for (size_t i = 0; i < triangles.size(); ++i) result.triangles.row(i) = triangles[i].transpose();
  acd::CheckTriangleMesh(result, path);
  return result;
}

}  // namespace acdplan::envs
