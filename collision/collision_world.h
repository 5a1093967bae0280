#pragma once
// The collision world: a robot against a workspace's obstacles, exactly (FCL OBBRSS BVH) or on
// the ACD hulls of the obstacles (FCL convex shapes in a broadphase tree).

#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <memory>

#include "collision/collision_mode.h"
#include "collision/obstacle_set.h"
#include "envs/robot.h"

namespace acdplan::collision {

/// Options for CollisionWorld; `{}` is valid.
struct CollisionWorldOptions {
  CollisionMode mode = CollisionMode::kHullsExact;  ///< Mode of IsValid(pose) / Clearance(pose).
};

/// A snapshot of a CollisionWorld's query counters (each counted atomically).
struct CollisionCounters {
  std::uint64_t checks = 0;               ///< IsValid() calls.
  std::uint64_t collisions = 0;           ///< IsValid() calls that answered false.
  std::uint64_t clearance_queries = 0;    ///< Clearance() calls.
  std::uint64_t hull_tests = 0;           ///< Narrow-phase tests of the robot against a hull.
  std::uint64_t exact_confirmations = 0;  ///< kHullsExact: hull hits tested on the piece's own
                                          ///< triangles.
};

/// The robot of `robot` among the obstacles of `obstacles`.
///
/// Geometry (FCL): 2D obstacles are prisms z in [-h/2, h/2] (h = obstacles.extrusion_height),
/// SE(2) poses are lifted to SE(3) (rotation about z), a disc robot is a cylinder and a polygon
/// robot a prism, both z in [-h/4, h/4], so no robot face is coplanar with an obstacle cap. A
/// point robot is located exactly (PointLocator) instead of being given a shape. In 3D the
/// robot is its mesh (exact) or its convex hull (kHulls).
///
/// Contract of IsValid(pose) (true = no contact; touching counts as contact):
///  - kBvh: the robot's exact geometry against one OBBRSS BVH over all obstacle triangles; as
///    triangle BVHs only see surfaces, a robot entirely inside an obstacle is found by locating
///    one robot point exactly, and (3D, closed robot mesh) an obstacle piece entirely inside the
///    robot by locating one of its vertices in the robot. 3D obstacle pieces that are open
///    meshes have no inside: only surface contact is seen there.
///  - kHulls: the robot's convex hull (its exact convex pieces for a non-convex polygon robot)
///    against the hulls of the obstacle pieces (for a concave 3D piece whose hull has many
///    faces, a polytope of few faces around it, internal/outer_polytope.h): conservative,
///    IsValid(pose, kHulls) implies IsValid(pose, kBvh).
///  - kHullsExact: each hull hit is confirmed on that piece's own triangles (and the same
///    containment tests on that piece): the same answer as kBvh up to floating-point ties on
///    a contact or on an ACD cut. A closed convex mesh robot is tested as a solid polytope
///    against the triangles near it (separating axes); any other robot by FCL's BVH-BVH test. A hit
///    on a convex piece needs no confirmation, unless (3D) its obstacle has a cavity part
///    (PointLocator's winding rule): there the hulls of the outer part cover the cavity.
/// Queries are const and thread-safe; the counters are atomic.
class CollisionWorld {
 public:
  /// @throws InputError if the robot does not fit the world (a disc or polygon robot in a
  ///         3D world, a mesh robot in a 2D world) or is invalid.
  CollisionWorld(std::shared_ptr<const ObstacleSet> obstacles, const envs::Robot& robot,
                 const CollisionWorldOptions& options = {});
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  /// True if the robot at `pose` touches no obstacle, in options().mode or `mode`.
  bool IsValid(const Eigen::Isometry3d& pose) const { return IsValid(pose, options_.mode); }
  bool IsValid(const Eigen::Isometry3d& pose, CollisionMode mode) const;
  /// SE(2) pose (2D worlds), lifted to SE(3).
  bool IsValid(const Eigen::Isometry2d& pose) const { return IsValid(Lift(pose)); }
  bool IsValid(const Eigen::Isometry2d& pose, CollisionMode mode) const {
    return IsValid(Lift(pose), mode);
  }

  /// Distance from the robot at `pose` to the nearest obstacle [units]; 0 when IsValid() is
  /// false (no penetration depth). kHulls gives a lower bound of kBvh's value (distance to the
  /// hulls); kHullsExact computes exact distances only for pieces whose hull is closer than the
  /// best so far, so it equals kBvh's value up to FCL's tolerance.
  double Clearance(const Eigen::Isometry3d& pose) const { return Clearance(pose, options_.mode); }
  double Clearance(const Eigen::Isometry3d& pose, CollisionMode mode) const;
  double Clearance(const Eigen::Isometry2d& pose) const { return Clearance(Lift(pose)); }
  double Clearance(const Eigen::Isometry2d& pose, CollisionMode mode) const {
    return Clearance(Lift(pose), mode);
  }

  CollisionCounters counters() const;
  void ResetCounters();

  const CollisionWorldOptions& options() const { return options_; }
  const ObstacleSet& obstacles() const { return *obstacles_; }
  const envs::Robot& robot() const { return robot_; }

  /// The SE(3) pose of an SE(2) pose: rotation about z, translation in the z = 0 plane.
  static Eigen::Isometry3d Lift(const Eigen::Isometry2d& pose);

 private:
  struct Impl;
  std::shared_ptr<const ObstacleSet> obstacles_;
  envs::Robot robot_;
  CollisionWorldOptions options_;
  std::unique_ptr<Impl> impl_;
  mutable std::atomic<std::uint64_t> checks_{0}, collisions_{0}, clearance_queries_{0},
      hull_tests_{0}, exact_confirmations_{0};
};

}  // namespace acdplan::collision
