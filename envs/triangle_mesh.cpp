#include "envs/triangle_mesh.h"

#include "base/input_error.h"

namespace acdplan::envs {

Eigen::AlignedBox3d BoundingBox(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    box.extend(Eigen::Vector3d(mesh.vertices.row(i).transpose()));
  }
  return box;
}

void CheckTriangleMesh(const TriangleMesh& mesh, const std::string& where) {
  if (mesh.triangles.rows() == 0) throw InputError(where + ": mesh has no triangles");
  if (!mesh.vertices.allFinite()) {
    throw InputError(where + ": mesh has a NaN or infinite vertex coordinate");
  }
  const Eigen::Index n = mesh.vertices.rows();
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int index = mesh.triangles(f, k);
      if (index < 0 || index >= n) {
        throw InputError(where + ": triangle " + std::to_string(f) + ": index " +
                         std::to_string(index) + " out of range [0, " + std::to_string(n) + ")");
      }
    }
  }
}

}  // namespace acdplan::envs
