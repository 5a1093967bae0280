#include "acd/internal/closed_shells.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <set>

#include "acd/internal/cgal_surface_mesh.h"
#include "acd/internal/side_of_mesh.h"

namespace acdplan::acd::internal {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Side = SideOfMesh<Mesh>;

}  // namespace

int VolumeSign(const TriangleMesh& mesh, const std::vector<int>& faces) {
  if (faces.empty()) return 0;
  // Tetrahedra about a vertex of the shell (MeshVolume's choice), not the origin, so that the
  // terms stay small for far meshes.
  const Eigen::Vector3d origin = mesh.vertices.row(mesh.triangles(faces[0], 0)).transpose();
  double sum = 0, magnitude = 0;
  for (const int f : faces) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0)).transpose() - origin;
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1)).transpose() - origin;
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2)).transpose() - origin;
    sum += a.dot(b.cross(c));
    // The permanent of |a|, |b|, |c|: the sum of the determinant's terms in absolute value.
    const Eigen::Vector3d x = a.cwiseAbs(), y = b.cwiseAbs(), z = c.cwiseAbs();
    magnitude += x.x() * (y.y() * z.z() + y.z() * z.y()) + x.y() * (y.z() * z.x() + y.x() * z.z()) +
                 x.z() * (y.x() * z.y() + y.y() * z.x());
  }
  // Each determinant (of rounded differences) is off by at most ~10 u times its permanent, and
  // the sum adds n u of the magnitude; twice that is a safe bound (u = 2^-53).
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const double bound = 2 * (10 + static_cast<double>(faces.size())) * u * magnitude;
  if (std::abs(sum) > bound) return sum > 0 ? 1 : -1;
  using Q = CGAL::Exact_rational;
  // Returns a value: with GMP's C++ numbers, `Q - Q` is an expression template holding
  // references to the two temporaries, which would dangle once the lambda returns.
  auto exact = [&](int v, int k) -> Q { return Q(mesh.vertices(v, k)) - Q(origin(k)); };
  Q total = 0;
  for (const int f : faces) {
    Q p[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) p[i][k] = exact(mesh.triangles(f, i), k);
    }
    total += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
             p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
             p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  return CGAL::sign(total);
}

int VolumeSign(const TriangleMesh& mesh) {
  std::vector<int> faces(static_cast<size_t>(mesh.triangles.rows()));
  std::iota(faces.begin(), faces.end(), 0);
  return VolumeSign(mesh, faces);
}

std::vector<std::vector<int>> EnclosingShells(const TriangleMesh& mesh,
                                              const std::vector<std::vector<int>>& shells) {
  const size_t count = shells.size();
  std::vector<Eigen::AlignedBox3d> boxes(count);
  std::vector<std::set<int>> vertices(count);
  for (size_t i = 0; i < count; ++i) {
    for (const int f : shells[i]) {
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.triangles(f, k);
        vertices[i].insert(v);
        boxes[i].extend(Eigen::Vector3d(mesh.vertices.row(v).transpose()));
      }
    }
  }
  // Built on first use: most shells enclose nothing.
  std::vector<std::unique_ptr<Mesh>> surfaces(count);
  std::vector<std::unique_ptr<Side>> sides(count);
  std::vector<std::vector<int>> enclosing(count);
  for (size_t i = 0; i < count; ++i) {
    for (size_t j = 0; j < count; ++j) {
      if (i == j || !boxes[j].contains(boxes[i])) continue;
      // A vertex of i off j: with no crossing, the whole of i is on its side of j.
      int probe = -1;
      for (const int v : vertices[i]) {
        if (!vertices[j].count(v)) {
          probe = v;
          break;
        }
      }
      if (probe < 0) continue;
      if (!sides[j]) {
        surfaces[j] = std::make_unique<Mesh>(ToSurfaceMesh<Epick>(mesh, shells[j]));
        sides[j] = std::make_unique<Side>(*surfaces[j]);
      }
      const Epick::Point_3 p(mesh.vertices(probe, 0), mesh.vertices(probe, 1),
                             mesh.vertices(probe, 2));
      if ((*sides[j])(p) == CGAL::ON_BOUNDED_SIDE) enclosing[i].push_back(static_cast<int>(j));
    }
  }
  return enclosing;
}

}  // namespace acdplan::acd::internal
