#pragma once
// How a CollisionWorld answers a query: exact BVH, ACD hulls, or hulls confirmed exactly.

#include <string>
#include <vector>

namespace acdplan::collision {

/// The three ways CollisionWorld checks the robot against the obstacles.
enum class CollisionMode {
  /// Exact: the robot against one OBBRSS BVH over every obstacle triangle (plus a containment
  /// test, since triangle BVHs only see surfaces).
  kBvh,
  /// Conservative: the robot against the convex hulls of the obstacles' ACD components in a
  /// broadphase tree. May report a collision near a concave obstacle feature (the hull covers
  /// more than the component); never misses one.
  kHulls,
  /// Exact: a hull hit is confirmed against that component's own triangles (and containment);
  /// the answers equal kBvh's. No confirmation is needed when the piece is convex, or (3D) when a
  /// corner of the robot lies in a convex polytope inside the piece (its hull with each face
  /// moved in past the piece's pockets, internal/inner_polytope.h).
  kHullsExact,
};

/// "bvh", "hulls" or "hulls+exact".
std::string ToString(CollisionMode mode);

/// Inverse of ToString().
/// @throws InputError "unknown collision mode '<name>' (expected one of: bvh, hulls,
///         hulls+exact)" for any other string.
CollisionMode ParseCollisionMode(const std::string& name);

/// Every mode, in declaration order.
std::vector<CollisionMode> AllCollisionModes();

}  // namespace acdplan::collision
