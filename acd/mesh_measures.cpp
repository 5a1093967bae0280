#include "acd/mesh_measures.h"

#include <cmath>

namespace acdplan::acd {
namespace {

Eigen::Vector3d Corner(const TriangleMesh& mesh, Eigen::Index face, int k) {
  return mesh.vertices.row(mesh.triangles(face, k)).transpose();
}

Eigen::Vector3d Origin(const TriangleMesh& mesh) {
  return mesh.vertices.rows() > 0 ? Eigen::Vector3d(mesh.vertices.row(0).transpose())
                                  : Eigen::Vector3d::Zero();
}

Eigen::Vector3d SurfaceCentroid(const TriangleMesh& mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = Corner(mesh, f, 0), b = Corner(mesh, f, 1), c = Corner(mesh, f, 2);
    const double w = 0.5 * (b - a).cross(c - a).norm();
    sum += w * (a + b + c) / 3.0;
    area += w;
  }
  if (area > 0) return sum / area;
  return mesh.vertices.rows() > 0 ? Eigen::Vector3d(mesh.vertices.colwise().mean().transpose())
                                  : Eigen::Vector3d::Zero();
}

}  // namespace

double MeshVolume(const TriangleMesh& mesh) {
  const Eigen::Vector3d o = Origin(mesh);
  double six_volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    six_volume +=
        (Corner(mesh, f, 0) - o).dot((Corner(mesh, f, 1) - o).cross(Corner(mesh, f, 2) - o));
  }
  return six_volume / 6.0;
}

double MeshArea(const TriangleMesh& mesh) {
  double area = 0.0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = Corner(mesh, f, 0);
    area += 0.5 * (Corner(mesh, f, 1) - a).cross(Corner(mesh, f, 2) - a).norm();
  }
  return area;
}

Eigen::Vector3d MeshCentroid(const TriangleMesh& mesh, bool solid) {
  if (!solid) return SurfaceCentroid(mesh);
  // Each face with the reference point o spans a tetrahedron whose signed volume weights its
  // centroid (o + a + b + c) / 4.
  const Eigen::Vector3d o = Origin(mesh);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double six_volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = Corner(mesh, f, 0) - o, b = Corner(mesh, f, 1) - o,
                          c = Corner(mesh, f, 2) - o;
    const double w = a.dot(b.cross(c));
    sum += w * (a + b + c) / 4.0;
    six_volume += w;
  }
  if (!(std::abs(six_volume) > 0)) return SurfaceCentroid(mesh);
  return o + sum / six_volume;
}

}  // namespace acdplan::acd
