#pragma once
// The robot: a point, a disc, a rigid polygon (SE(2)) or a rigid mesh (SE(3)).

#include <Eigen/Geometry>
#include <string>

#include "acd/polygon2d.h"
#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Which geometry a Robot has.
enum class RobotShape {
  kPoint,    ///< A point moving in R^2 or R^3 (configuration = position).
  kDisc,     ///< A disc of `radius` in the plane (configuration = position; rotation is moot).
  kPolygon,  ///< A rigid polygon in the plane (configuration = SE(2) pose).
  kMesh,     ///< A rigid triangle mesh in space (configuration = SE(3) pose).
};

/// A robot's geometry in its body frame; the body origin is the reference point of a pose.
/// Build with the factory functions, which validate.
struct Robot {
  RobotShape shape = RobotShape::kPoint;
  double radius = 0.0;     ///< kDisc: radius [units], > 0.
  acd::Polygon2d polygon;  ///< kPolygon: body-frame outline, prepared (CCW, holes CW).
  acd::TriangleMesh mesh;  ///< kMesh: body-frame surface.

  static Robot Point();
  /// @throws InputError unless `radius` is finite and > 0.
  static Robot Disc(double radius);
  /// Prepares `outline` (acd::PreparePolygon).
  /// @throws InputError if it is not a valid polygon.
  static Robot Polygon(const acd::Polygon2d& outline);
  /// @throws InputError if acd::CheckTriangleMesh() fails.
  static Robot Mesh(const acd::TriangleMesh& surface);

  /// Largest distance from the body origin to the robot's geometry (0 for a point) [units].
  double BoundingRadius() const;
};

/// Name of a shape: "point", "disc", "polygon", "mesh".
std::string ToString(RobotShape shape);

/// Inverse of ToString().
/// @throws InputError "unknown robot shape '<name>' (expected one of: point, disc, polygon, mesh)".
RobotShape ParseRobotShape(const std::string& name);

/// True if the 2D robot's geometry at `pose` lies inside `bounds` (a planner's state space
/// bounds only the reference point; the world's edges are no obstacles). False for a mesh.
bool InsideBounds(const Robot& robot, const Eigen::AlignedBox2d& bounds,
                  const Eigen::Isometry2d& pose);

/// `polygon` moved by the SE(2) `pose` (rotation then translation), every ring.
acd::Polygon2d Transformed(const acd::Polygon2d& polygon, const Eigen::Isometry2d& pose);

/// `mesh` moved by the SE(3) `pose`.
acd::TriangleMesh Transformed(const acd::TriangleMesh& mesh, const Eigen::Isometry3d& pose);

}  // namespace acdplan::envs
