#pragma once
// A triangle mesh: the input of the 3D decomposition and the 3D obstacle and robot geometry.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace acdplan::acd {

/// An indexed triangle mesh (libigl's V, F convention).
struct TriangleMesh {
  Eigen::Matrix<double, Eigen::Dynamic, 3> vertices;  ///< #V by 3 vertex positions [units].
  Eigen::Matrix<int, Eigen::Dynamic, 3> triangles;    ///< #F by 3 indices into `vertices`,
                                                      ///< counter-clockwise seen from outside.
};

/// The mesh with vertex rows `vertices` and triangle rows `triangles`.
TriangleMesh MakeTriangleMesh(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<Eigen::Vector3i>& triangles);

/// Axis-aligned bounding box of the vertices (empty box for an empty mesh).
Eigen::AlignedBox3d BoundingBox(const TriangleMesh& mesh);

/// The same mesh numbered by its geometry alone: vertices in lexicographic (x, y, z) order
/// (stable, so equal positions keep their order), each triangle rotated to start at its least
/// vertex (its orientation kept), triangles in lexicographic order. Two numberings of one mesh
/// give the same bytes, so what a computation settles by index no longer depends on the file.
TriangleMesh CanonicallyNumbered(const TriangleMesh& mesh);

/// A cube of side `side` [units] centred on the origin, axis-aligned, 8 vertices and 12
/// triangles counter-clockwise seen from outside (a robot or obstacle for tests and benchmarks).
TriangleMesh Cube(double side);

/// Checks that `mesh` has at least one triangle, finite coordinates and every index in
/// [0, #V).
/// @throws InputError "<where>: <rule>", e.g. "cup.obj: triangle 4: index 17 out of
///         range [0, 12)".
void CheckTriangleMesh(const TriangleMesh& mesh, const std::string& where);

}  // namespace acdplan::acd
