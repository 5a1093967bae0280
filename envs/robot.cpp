#include "envs/robot.h"

#include <algorithm>
#include <cmath>

#include "acd/prepare_polygon.h"
#include "base/enum_names.h"
#include "base/input_error.h"

namespace acdplan::envs {

Robot Robot::Point() { return Robot{}; }

Robot Robot::Disc(double radius) {
  if (!std::isfinite(radius) || !(radius > 0.0)) {
    throw InputError("Robot::Disc(): radius must be finite and > 0, got " + std::to_string(radius));
  }
  Robot robot;
  robot.shape = RobotShape::kDisc;
  robot.radius = radius;
  return robot;
}

Robot Robot::Polygon(const acd::Polygon2d& outline) {
  Robot robot;
  robot.shape = RobotShape::kPolygon;
  robot.polygon = acd::PreparePolygon(outline, "Robot::Polygon()");
  return robot;
}

Robot Robot::Mesh(const acd::TriangleMesh& surface) {
  acd::CheckTriangleMesh(surface, "Robot::Mesh()");
  Robot robot;
  robot.shape = RobotShape::kMesh;
  robot.mesh = surface;
  return robot;
}

double Robot::BoundingRadius() const {
  switch (shape) {
    case RobotShape::kPoint:
      return 0.0;
    case RobotShape::kDisc:
      return radius;
    case RobotShape::kPolygon: {
      double r = 0.0;
      for (const acd::Point2d& p : polygon.outer) r = std::max(r, p.norm());
      return r;
    }
    case RobotShape::kMesh:
      return mesh.vertices.rows() == 0 ? 0.0 : mesh.vertices.rowwise().norm().maxCoeff();
  }
  return 0.0;
}

namespace {

constexpr std::array<EnumName<RobotShape>, 4> kShapes = {{
    {RobotShape::kPoint, "point"},
    {RobotShape::kDisc, "disc"},
    {RobotShape::kPolygon, "polygon"},
    {RobotShape::kMesh, "mesh"},
}};

}  // namespace

std::string ToString(RobotShape shape) { return NameOf(kShapes, shape); }

RobotShape ParseRobotShape(const std::string& name) {
  return ValueOf(kShapes, name, "robot shape");
}

acd::Polygon2d Transformed(const acd::Polygon2d& polygon, const Eigen::Isometry2d& pose) {
  auto move = [&pose](const acd::Ring2d& ring) {
    acd::Ring2d out;
    out.reserve(ring.size());
    for (const acd::Point2d& p : ring) out.push_back(pose * p);
    return out;
  };
  acd::Polygon2d result{move(polygon.outer), {}};
  for (const acd::Ring2d& hole : polygon.holes) result.holes.push_back(move(hole));
  return result;
}

acd::TriangleMesh Transformed(const acd::TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  acd::TriangleMesh result = mesh;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    result.vertices.row(i) = (pose * Eigen::Vector3d(mesh.vertices.row(i).transpose())).transpose();
  }
  return result;
}

bool InsideBounds(const Robot& robot, const Eigen::AlignedBox2d& bounds,
                  const Eigen::Isometry2d& pose) {
  switch (robot.shape) {
    case RobotShape::kPoint:
      return bounds.contains(pose.translation());
    case RobotShape::kDisc: {
      const Eigen::Vector2d r(robot.radius, robot.radius);
      return bounds.contains(Eigen::AlignedBox2d(pose.translation() - r, pose.translation() + r));
    }
    case RobotShape::kPolygon:
      for (const acd::Point2d& p : robot.polygon.outer) {
        if (!bounds.contains(pose * p)) return false;
      }
      return true;
    case RobotShape::kMesh:
      return false;
  }
  return false;
}

}  // namespace acdplan::envs
