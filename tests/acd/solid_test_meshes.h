#pragma once
// Small closed meshes with known decompositions for the solid ACD tests.

#include <cmath>
#include <vector>

#include "acd/internal/triangulate_ring.h"
#include "acd/prepare_mesh.h"
#include "acd/triangle_mesh.h"

namespace acdplan::acd::test {

/// The prism over the counter-clockwise simple ring `ring` (in x, y), from z = 0 to `height`.
inline TriangleMesh Extrude(const Ring2d& ring, double height) {
  const int n = static_cast<int>(ring.size());
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : ring) v.emplace_back(p.x(), p.y(), 0.0);
  for (const auto& p : ring) v.emplace_back(p.x(), p.y(), height);
  std::vector<Eigen::Vector3i> f;
  for (const auto& t : internal::TriangulateRing(ring)) {
    f.emplace_back(t[0], t[2], t[1]);              // bottom, seen from below
    f.emplace_back(n + t[0], n + t[1], n + t[2]);  // top
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    f.emplace_back(i, j, n + j);
    f.emplace_back(i, n + j, n + i);
  }
  return MakeTriangleMesh(v, f);
}

/// An L-shaped block: [0,2]x[0,1] plus [0,1]x[1,2], height 1.
inline TriangleMesh LBlock() {
  return Extrude({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1.0);
}

/// A U-shaped block: a 3x1 base with two 1x1 posts, height 1.
inline TriangleMesh UBlock() {
  return Extrude({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1.0);
}

/// An axis-aligned box from `lo` to `hi`; outward, or inward (a cavity shell) if `inward`.
inline TriangleMesh Box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool inward = false) {
  TriangleMesh cube = Cube(1.0);
  for (Eigen::Index i = 0; i < cube.vertices.rows(); ++i) {
    for (int k = 0; k < 3; ++k) cube.vertices(i, k) = cube.vertices(i, k) < 0 ? lo(k) : hi(k);
  }
  if (inward) cube.triangles.col(1).swap(cube.triangles.col(2));
  return cube;
}

/// A torus about the z axis with radii `major` > `minor`, `nu` x `nv` quads split in two.
inline TriangleMesh Torus(double major, double minor, int nu, int nv) {
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> f;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < nu; ++i) {
    const double u = 2 * pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double w = 2 * pi * j / nv;
      const double r = major + minor * std::cos(w);
      v.emplace_back(r * std::cos(u), r * std::sin(u), minor * std::sin(w));
    }
  }
  auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      f.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      f.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return MakeTriangleMesh(v, f);
}

/// Two shells as one mesh (e.g. a box and the cavity inside it).
inline TriangleMesh Concatenate(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh out;
  out.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  out.vertices << a.vertices, b.vertices;
  out.triangles.resize(a.triangles.rows() + b.triangles.rows(), 3);
  out.triangles << a.triangles,
      (b.triangles.array() + static_cast<int>(a.vertices.rows())).matrix();
  return out;
}

/// A PreparedMesh for a closed, clean, outward mesh: one part, no defects.
inline PreparedMesh PreparedSolid(const TriangleMesh& mesh) {
  PreparedMesh prepared;
  prepared.mesh = mesh;
  prepared.parts = {mesh};
  return prepared;
}

}  // namespace acdplan::acd::test
