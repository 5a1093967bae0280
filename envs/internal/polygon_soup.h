#pragma once
// The vertices and polygonal faces a mesh file holds, as its reader collects them, and their
// triangulation: what the OBJ, OFF and PLY readers share.

#include <string>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::envs::internal {

/// A mesh's vertices and polygonal faces as read; Finish() triangulates them.
class PolygonSoup {
 public:
  std::vector<Eigen::Vector3d> vertices;

  /// A face of 0-based vertex indices, checked by the reader (in range, at least 3).
  void AddFace(const std::vector<int>& corners);

  /// The triangles of every face, vertices no face uses dropped, the others in their order. A
  /// triangle is kept as given; a larger face is projected along its Newell normal's largest
  /// axis and, if strictly convex there, fanned from its first corner, as other readers do (the
  /// choice of diagonals matters where modellers leave faces non-planar, or overlapping each
  /// other), else ear-clipped (acd::internal::TriangulateRing; a fan if it has no area at all),
  /// counter-clockwise about its normal as the face is.
  /// @throws InputError "<source>: no triangles in file", or CheckTriangleMesh()'s error.
  acd::TriangleMesh Finish(const std::string& source) const;

 private:
  void AppendTriangles(const std::vector<int>& face, std::vector<Eigen::Vector3i>* out) const;

  std::vector<int> corners_;       // The faces' corners, one face after the other.
  std::vector<size_t> face_ends_;  // Where each face's corners end in corners_.
};

}  // namespace acdplan::envs::internal
