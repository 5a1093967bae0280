#include "envs/internal/polygon_soup.h"

#include <array>
#include <utility>

#include "acd/internal/triangulate_ring.h"
#include "base/input_error.h"

namespace acdplan::envs::internal {

void PolygonSoup::AddFace(const std::vector<int>& corners) {
  corners_.insert(corners_.end(), corners.begin(), corners.end());
  face_ends_.push_back(corners_.size());
}

acd::TriangleMesh PolygonSoup::Finish(const std::string& source) const {
  std::vector<Eigen::Vector3i> triangles;
  std::vector<int> face;
  for (size_t f = 0, begin = 0; f < face_ends_.size(); begin = face_ends_[f++]) {
    face.assign(corners_.begin() + static_cast<std::ptrdiff_t>(begin),
                corners_.begin() + static_cast<std::ptrdiff_t>(face_ends_[f]));
    AppendTriangles(face, &triangles);
  }
  if (triangles.empty()) throw InputError(source + ": no triangles in file");
  std::vector<int> index(vertices.size(), -1);
  for (const Eigen::Vector3i& t : triangles) {
    for (const int v : t) index[v] = 0;
  }
  std::vector<Eigen::Vector3d> used;
  for (size_t v = 0; v < vertices.size(); ++v) {
    if (index[v] == 0) {
      index[v] = static_cast<int>(used.size());
      used.push_back(vertices[v]);
    }
  }
  for (Eigen::Vector3i& t : triangles) t = Eigen::Vector3i(index[t[0]], index[t[1]], index[t[2]]);
  acd::TriangleMesh mesh = acd::MakeTriangleMesh(used, triangles);
  acd::CheckTriangleMesh(mesh, source);
  return mesh;
}

// Finish()'s triangles of one face (see there).
void PolygonSoup::AppendTriangles(const std::vector<int>& face,
                                  std::vector<Eigen::Vector3i>* out) const {
  const size_t k = face.size();
  if (k == 3) {
    out->emplace_back(face[0], face[1], face[2]);
    return;
  }
  // Relative to the first corner: a face 4.5e6 from the origin keeps its small features.
  const Eigen::Vector3d& origin = vertices[face[0]];
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (size_t i = 1; i + 1 < k; ++i) {
    normal += (vertices[face[i]] - origin).cross(vertices[face[i + 1]] - origin);
  }
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  if (normal[axis] == 0.0) {
    for (size_t i = 1; i + 1 < k; ++i) out->emplace_back(face[0], face[i], face[i + 1]);
    return;
  }
  // (u, v, axis) is right-handed when the normal points along +axis: the face projects
  // counter-clockwise either way.
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  if (normal[axis] < 0.0) std::swap(u, v);
  acd::Ring2d ring;
  ring.reserve(k);
  for (const int corner : face) {
    const Eigen::Vector3d p = vertices[corner] - origin;
    ring.emplace_back(p[u], p[v]);
  }
  bool strictly_convex = true;
  for (size_t i = 0; i < k && strictly_convex; ++i) {
    const acd::Point2d& a = ring[i];
    const acd::Point2d& b = ring[(i + 1) % k];
    const acd::Point2d& c = ring[(i + 2) % k];
    strictly_convex = (b - a).x() * (c - b).y() - (b - a).y() * (c - b).x() > 0.0;
  }
  if (strictly_convex) {
    for (size_t i = 1; i + 1 < k; ++i) out->emplace_back(face[0], face[i], face[i + 1]);
    return;
  }
  for (const std::array<int, 3>& t : acd::internal::TriangulateRing(ring)) {
    out->emplace_back(face[t[0]], face[t[1]], face[t[2]]);
  }
}

}  // namespace acdplan::envs::internal
