#include "planning/plan_picture3d.h"

#include <algorithm>
#include <string>

#include "envs/robot.h"
#include "planning/plan_scenario3d.h"

namespace acdplan::planning {

namespace {

// A square prism of half-side `r` from `a` to `b` (8 vertices, 12 triangles).
acd::TriangleMesh Segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
  const Eigen::Vector3d d = b - a;
  if (!(d.norm() > 0)) return {};
  const Eigen::Vector3d u = d.normalized().unitOrthogonal() * r;
  const Eigen::Vector3d v = d.normalized().cross(u);
  acd::TriangleMesh box = acd::Cube(1.0);
  for (Eigen::Index i = 0; i < box.vertices.rows(); ++i) {
    const Eigen::Vector3d c = box.vertices.row(i).transpose() * 2.0;  // Corners at +-1.
    const Eigen::Vector3d p = a + (c.x() + 1) / 2 * d + c.y() * u + c.z() * v;
    box.vertices.row(i) = p.transpose();
  }
  // (u, v, d) may be left-handed: keep the faces outward.
  if (u.cross(v).dot(d) < 0) box.triangles.col(1).swap(box.triangles.col(2));
  return box;
}

acd::TriangleMesh Merge(const std::vector<acd::TriangleMesh>& meshes) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (const acd::TriangleMesh& mesh : meshes) {
    const int base = static_cast<int>(vertices.size());
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
      vertices.push_back(mesh.vertices.row(i).transpose());
    }
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      triangles.push_back(mesh.triangles.row(f).transpose() + Eigen::Vector3i::Constant(base));
    }
  }
  return acd::MakeTriangleMesh(vertices, triangles);
}

}  // namespace

std::vector<acd::SceneMesh3d> PlanScene3d(const Scenario& scenario, const PlanResult& result) {
  std::vector<acd::SceneMesh3d> scene;
  const envs::Workspace3d& world = scenario.workspace3d;
  const double diagonal = world.bounds.sizes().norm();
  for (size_t i = 0; i < world.obstacles.size(); ++i) {
    scene.push_back({"obstacle_" + std::to_string(i), world.obstacles[i],
                     Eigen::Vector3d(0.55, 0.57, 0.6), 0.45, false});
  }
  if (result.decomposition3d) {
    const auto& openings = result.decomposition3d->openings;
    for (size_t i = 0; i < openings.size(); ++i) {
      const std::vector<Eigen::Vector3d>& polygon = openings[i].polygon;
      std::vector<Eigen::Vector3i> fan;
      for (int k = 1; k + 1 < static_cast<int>(polygon.size()); ++k) fan.emplace_back(0, k, k + 1);
      if (fan.empty()) continue;
      scene.push_back({"opening_" + std::to_string(i), acd::MakeTriangleMesh(polygon, fan),
                       Eigen::Vector3d(0.96, 0.55, 0.1), 0.85, true});
    }
  }
  const bool mesh = scenario.robot.shape == envs::RobotShape::kMesh;
  auto robot_at = [&](const Eigen::Isometry3d& pose) {
    if (mesh) return envs::Transformed(scenario.robot.mesh, pose);
    acd::TriangleMesh cube = acd::Cube(0.012 * diagonal);
    for (Eigen::Index i = 0; i < cube.vertices.rows(); ++i) {
      cube.vertices.row(i) += pose.translation().transpose();
    }
    return cube;
  };
  if (result.path.size() >= 2) {
    std::vector<acd::TriangleMesh> tube;
    for (size_t i = 0; i + 1 < result.path.size(); ++i) {
      tube.push_back(Segment(PoseOfReals(result.path[i]).translation(),
                             PoseOfReals(result.path[i + 1]).translation(), 0.003 * diagonal));
    }
    scene.push_back({"path", Merge(tube), Eigen::Vector3d(0.88, 0.19, 0.19), 1.0, false});
    const size_t n = result.path.size();
    const size_t poses = std::min<size_t>(8, n - 2);
    for (size_t k = 1; k <= poses; ++k) {
      const size_t index = k * (n - 1) / (poses + 1);
      scene.push_back({"robot_" + std::to_string(k), robot_at(PoseOfReals(result.path[index])),
                       Eigen::Vector3d(0.79, 0.16, 0.16), 0.6, false});
    }
  }
  scene.push_back({"start", robot_at(PoseFromXyzRpy(scenario.start)),
                   Eigen::Vector3d(0.17, 0.54, 0.24), 1.0, false});
  scene.push_back({"goal", robot_at(PoseFromXyzRpy(scenario.goal)),
                   Eigen::Vector3d(0.53, 0.18, 0.61), 1.0, false});
  return scene;
}

}  // namespace acdplan::planning
