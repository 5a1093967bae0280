#pragma once
// Pinch vertices: where a closed surface meets itself in several fans of triangles (two parts
// touching at a point, a cavity touching the outer shell), and their separation into a
// 2-manifold.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace acdplan::acd::internal {

/// The fans around vertex `v` of `faces` (indices into `triangles`, each with a corner at v):
/// faces joined across their edges through v. (*fan)[i] is the fan of faces[i], fans numbered
/// 0, 1, ... in the order of their first face in `faces`. Returns the number of fans.
int FansAroundVertex(const std::vector<std::array<int, 3>>& triangles,
                     const std::vector<int>& faces, int v, std::vector<int>* fan);

/// Gives each fan of triangles around a pinch vertex (one where `triangles`, joined across
/// their edges through it, form several fans) its own copy of the vertex, moved toward the
/// centroid of that fan's corners by 1e-3 of the shortest edge at the vertex: far above
/// rounding, far below the fan's size. A fan whose triangles face away from that centroid (the
/// solid is outside its cone: a cavity touching the outer shell, the waist of a solid that
/// closes to a point) moves into its own cone, which adds a hair of solid; a fan that faces
/// toward it (the tip of a lobe) moves into its own solid. When both kinds meet, the first fan
/// of the second kind stays in place: the cone of the others can lie inside its solid (a
/// cavity's cone inside the outer shell's), so moving it could cross them. `group`, when not
/// empty, gives each triangle a group (e.g. the solid part it belongs to), and only fans of one
/// group are separated: a vertex that two groups share, one fan each, is left as it is. New
/// copies are appended to `vertices`. A pinch whose shortest edge is so short that 1e-3 of it
/// is below 16 units in the last place of its coordinates (an earlier separation at rounding
/// level) is left as it is: its copies would round back onto it. The caller checks the result
/// for crossings (rounding or nearly tangent fans can make them) and for pinches left.
/// Complexity: O(F log F) for F triangles.
struct PinchSeparation {
  int separated = 0;  ///< Pinch vertices given a copy per fan.
  int left = 0;       ///< Pinch vertices too small to separate, left as they are.
};
PinchSeparation SeparatePinches(std::vector<Eigen::Vector3d>* vertices,
                                std::vector<std::array<int, 3>>* triangles,
                                const std::vector<int>& group = {});

/// The vertices < `vertex_count` where one group's triangles (`group` as for SeparatePinches())
/// form several fans; `*first` is the lowest (-1 if none) and `*fans_at_first` its fan count.
int CountPinches(const std::vector<std::array<int, 3>>& triangles, size_t vertex_count,
                 const std::vector<int>& group, int* first, int* fans_at_first);

}  // namespace acdplan::acd::internal
