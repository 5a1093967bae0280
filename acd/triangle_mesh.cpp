#include "acd/triangle_mesh.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

#include "base/input_error.h"

namespace acdplan::acd {

TriangleMesh MakeTriangleMesh(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<Eigen::Vector3i>& triangles) {
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i) {
    mesh.vertices.row(static_cast<Eigen::Index>(i)) = vertices[i];
  }
  mesh.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t i = 0; i < triangles.size(); ++i) {
    mesh.triangles.row(static_cast<Eigen::Index>(i)) = triangles[i];
  }
  return mesh;
}

Eigen::AlignedBox3d BoundingBox(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    box.extend(Eigen::Vector3d(mesh.vertices.row(i).transpose()));
  }
  return box;
}

TriangleMesh CanonicallyNumbered(const TriangleMesh& mesh) {
  const Eigen::Index nv = mesh.vertices.rows(), nf = mesh.triangles.rows();
  std::vector<int> order(static_cast<size_t>(nv));
  std::iota(order.begin(), order.end(), 0);
  auto position = [&](int v) {
    return std::make_tuple(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return position(a) < position(b); });
  TriangleMesh out;
  out.vertices.resize(nv, 3);
  std::vector<int> id(static_cast<size_t>(nv));
  for (size_t i = 0; i < order.size(); ++i) {
    out.vertices.row(static_cast<Eigen::Index>(i)) = mesh.vertices.row(order[i]);
    id[static_cast<size_t>(order[i])] = static_cast<int>(i);
  }
  std::vector<std::array<int, 3>> triangles(static_cast<size_t>(nf));
  for (Eigen::Index f = 0; f < nf; ++f) {
    std::array<int, 3>& t = triangles[static_cast<size_t>(f)];
    for (int k = 0; k < 3; ++k)
      t[static_cast<size_t>(k)] = id[static_cast<size_t>(mesh.triangles(f, k))];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  }
  std::sort(triangles.begin(), triangles.end());
  out.triangles.resize(nf, 3);
  for (Eigen::Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k)
      out.triangles(f, k) = triangles[static_cast<size_t>(f)][static_cast<size_t>(k)];
  }
  return out;
}

TriangleMesh Cube(double side) {
  TriangleMesh mesh;
  mesh.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) {  // Bit k of i: the +side/2 end of axis k.
    mesh.vertices.row(i) << ((i & 1) ? 0.5 : -0.5) * side, ((i & 2) ? 0.5 : -0.5) * side,
        ((i & 4) ? 0.5 : -0.5) * side;
  }
  mesh.triangles.resize(12, 3);
  mesh.triangles << 0, 2, 1, 1, 2, 3,  // z-
      4, 5, 6, 5, 7, 6,                // z+
      0, 1, 4, 1, 5, 4,                // y-
      2, 6, 3, 3, 6, 7,                // y+
      0, 4, 2, 2, 4, 6,                // x-
      1, 3, 5, 3, 7, 5;                // x+
  return mesh;
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

}  // namespace acdplan::acd
