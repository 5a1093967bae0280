#pragma once
// Small closed meshes with known decompositions for the solid ACD tests.

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/decomposition3d.h"
#include "acd/internal/solid_openings.h"
#include "acd/internal/triangulate_ring.h"
#include "acd/prepare_mesh.h"
#include "acd/triangle_mesh.h"
#include "base/random.h"

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

/// A tetrahedron of four points coplanar on a lattice of spacing 1e-6 but not once rounded to
/// doubles: a valid solid of volume about 2e-33, all of it rounding. Outward by the exact sign.
inline TriangleMesh LatticeSliver() {
  const double s = 1e-6;
  return MakeTriangleMesh(
      {{3 * s, 2 * s, 6 * s}, {8 * s, 9 * s, 0}, {4 * s, 3 * s, 6 * s}, {9 * s, 10 * s, 0}},
      {{1, 0, 2}, {3, 1, 2}, {1, 3, 0}, {0, 3, 2}});
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

/// The index of the vertex of `mesh` at `p`, or -1.
inline int VertexAt(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  for (int v = 0; v < mesh.vertices.rows(); ++v) {
    if (mesh.vertices.row(v).transpose() == p) return v;
  }
  return -1;
}

/// `solid` (closed, outward) with a tetrahedral cavity whose first corner is the solid's vertex
/// `corner` (the same index: the surface touches itself there) and whose other three corners
/// lie `size` x (1, 1/2, 1/2), (1/2, 1, 1/2), (1/2, 1/2, 1) from it, each axis's sign given by
/// `inward`, so inside the solid at a convex corner. Its first triangle starts at `corner`.
inline TriangleMesh WithCavityAtCorner(const TriangleMesh& solid, int corner,
                                       const Eigen::Vector3d& inward, double size) {
  const Eigen::Vector3d c = solid.vertices.row(corner).transpose();
  const int n = static_cast<int>(solid.vertices.rows());
  TriangleMesh out = solid;
  out.vertices.conservativeResize(n + 3, 3);
  const Eigen::Vector3d offsets[] = {{1, 0.5, 0.5}, {0.5, 1, 0.5}, {0.5, 0.5, 1}};
  for (int i = 0; i < 3; ++i) {
    out.vertices.row(n + i) = (c + size * inward.cwiseProduct(offsets[i])).transpose();
  }
  std::vector<Eigen::Vector3i> cavity = {
      {corner, n, n + 1}, {corner, n + 1, n + 2}, {corner, n + 2, n}, {n, n + 2, n + 1}};
  const Eigen::Vector3d a = out.vertices.row(n).transpose() - c,
                        b = out.vertices.row(n + 1).transpose() - c,
                        d = out.vertices.row(n + 2).transpose() - c;
  // As listed, the faces enclose volume -det(a, b, d) / 6: a cavity when det > 0.
  if (a.dot(b.cross(d)) < 0) {
    for (Eigen::Vector3i& t : cavity) std::swap(t(1), t(2));
  }
  out.triangles.conservativeResize(solid.triangles.rows() + 4, 3);
  for (int i = 0; i < 4; ++i)
    out.triangles.row(solid.triangles.rows() + i) = cavity[static_cast<size_t>(i)];
  return out;
}

/// A PreparedMesh for a closed, clean, outward mesh: one part, no defects.
inline PreparedMesh PreparedSolid(const TriangleMesh& mesh) {
  PreparedMesh prepared;
  prepared.mesh = mesh;
  prepared.parts = {mesh};
  return prepared;
}

/// True if every directed edge is met by its reverse exactly once: closed, 2-manifold at its
/// edges, consistently oriented.
inline bool IsClosed(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) ++directed[{mesh.triangles(f, k), mesh.triangles(f, (k + 1) % 3)}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    auto it = directed.find({edge.second, edge.first});
    if (it == directed.end() || it->second != 1) return false;
  }
  return true;
}

/// `mesh` renumbered at random from `seed`: vertices and triangles permuted, each triangle's
/// corners rotated (its orientation kept). The same solid, numbered as another file might.
inline TriangleMesh Renumbered(const TriangleMesh& mesh, std::uint64_t seed) {
  RandomEngine rng(seed);
  auto permutation = [&](Eigen::Index n) {
    std::vector<int> p(static_cast<size_t>(n));
    std::iota(p.begin(), p.end(), 0);
    for (size_t i = p.size(); i > 1; --i) std::swap(p[i - 1], p[UniformIndex(rng, i)]);
    return p;
  };
  const std::vector<int> vertex = permutation(mesh.vertices.rows());
  const std::vector<int> face = permutation(mesh.triangles.rows());
  TriangleMesh out = mesh;
  for (size_t i = 0; i < vertex.size(); ++i) {
    out.vertices.row(vertex[i]) = mesh.vertices.row(static_cast<Eigen::Index>(i));
  }
  for (size_t f = 0; f < face.size(); ++f) {
    const int turn = static_cast<int>(UniformIndex(rng, 3));
    for (int k = 0; k < 3; ++k) {
      out.triangles(face[f], k) =
          vertex[static_cast<size_t>(mesh.triangles(static_cast<Eigen::Index>(f), (k + turn) % 3))];
    }
  }
  return out;
}

/// Every byte of the mesh: vertex coordinates, then triangle corners (for byte-for-byte
/// reproducibility checks).
inline std::string Bytes(const TriangleMesh& mesh) {
  std::string bytes(reinterpret_cast<const char*>(mesh.vertices.data()),
                    sizeof(double) * static_cast<size_t>(mesh.vertices.size()));
  bytes.append(reinterpret_cast<const char*>(mesh.triangles.data()),
               sizeof(int) * static_cast<size_t>(mesh.triangles.size()));
  return bytes;
}

}  // namespace acdplan::acd::test

namespace acdplan::acd::test {

/// A minimal OBJ reader for acd-only tests: `v` and `f` lines (polygons fanned, `a/b/c` and
/// negative indices understood), vertices at identical positions merged, faces that repeat a
/// vertex dropped. Returns an empty mesh if the file cannot be read.
inline TriangleMesh ReadObjForTest(const std::string& path) {
  std::ifstream in(path);
  std::vector<Eigen::Vector3d> raw;
  std::vector<Eigen::Vector3i> faces;
  std::string line;
  std::vector<std::vector<int>> polygons;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Eigen::Vector3d p;
      s >> p.x() >> p.y() >> p.z();
      raw.push_back(p);
    } else if (tag == "f") {
      std::vector<int> poly;
      std::string token;
      while (s >> token) {
        const int i = std::stoi(token.substr(0, token.find('/')));
        poly.push_back(i < 0 ? static_cast<int>(raw.size()) + i : i - 1);
      }
      polygons.push_back(poly);
    }
  }
  std::map<std::tuple<double, double, double>, int> weld;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> id(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    auto [it, inserted] = weld.emplace(std::make_tuple(raw[i].x(), raw[i].y(), raw[i].z()),
                                       static_cast<int>(vertices.size()));
    if (inserted) vertices.push_back(raw[i]);
    id[i] = it->second;
  }
  for (const auto& poly : polygons) {
    for (size_t k = 1; k + 1 < poly.size(); ++k) {
      const Eigen::Vector3i t(id[static_cast<size_t>(poly[0])], id[static_cast<size_t>(poly[k])],
                              id[static_cast<size_t>(poly[k + 1])]);
      if (t(0) != t(1) && t(1) != t(2) && t(0) != t(2)) faces.push_back(t);
    }
  }
  return MakeTriangleMesh(vertices, faces);
}

/// A hand-made solid decomposition: one root cut by `plane` into leaves holding `components` (in
/// order), with the openings ComputeOpenings() finds between them.
inline Decomposition3d OneCut(const Plane3d& plane, std::vector<Component3d> components) {
  Decomposition3d d;
  HierarchyNode3d root;
  root.cut = plane;
  d.tree.push_back(root);
  d.roots = {0};
  for (Component3d& c : components) {
    HierarchyNode3d leaf;
    leaf.parent = 0;
    leaf.depth = 1;
    leaf.component = static_cast<int>(d.components.size());
    d.tree[0].children.push_back(static_cast<int>(d.tree.size()));
    d.tree.push_back(leaf);
    d.components.push_back(std::move(c));
  }
  internal::ComputeOpenings(&d);
  return d;
}

}  // namespace acdplan::acd::test
