#pragma once
// Shared fixtures of the collision tests: the built-in 2D worlds, robots, seeded poses.

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "acd/triangle_mesh.h"
#include "base/random.h"
#include "envs/generators.h"
#include "envs/robot.h"
#include "envs/workspace3d.h"
#include "tests/asan_build.h"

namespace acdplan::collision::testing {

/// Poses per world and robot in the randomized tests. 10^5 in a normal build (a few seconds in
/// Release); sanitizer builds run the same code ~20x slower, so they check 10^4 poses, still
/// enough to cross every obstacle feature of the built-in worlds many times.
#if ACDPLAN_ASAN_BUILD
constexpr int kPosesPerWorld = 10000;
#else
constexpr int kPosesPerWorld = 100000;
#endif

/// Whether this is a sanitizer build: the 3D ACD of the obstacles runs ~20x slower there, so
/// the 3D tests decompose the small meshes only.
constexpr bool kSanitizerBuild = ACDPLAN_ASAN_BUILD;

/// A non-convex L-shaped robot, about 0.6 x 0.4 units, body origin inside it.
inline envs::Robot LRobot() {
  acd::Polygon2d outline;
  outline.outer = {{-0.3, -0.2}, {0.3, -0.2}, {0.3, 0.0}, {-0.1, 0.0}, {-0.1, 0.2}, {-0.3, 0.2}};
  return envs::Robot::Polygon(outline);
}

/// A cube mesh of side `side` centred on the body origin (acd::Cube).
inline acd::TriangleMesh CubeMesh(double side) { return acd::Cube(side); }

/// `mesh` moved by `offset`.
inline acd::TriangleMesh Translated(acd::TriangleMesh mesh, const Eigen::Vector3d& offset) {
  mesh.vertices.rowwise() += offset.transpose();
  return mesh;
}

/// `mesh` with every face turned over (a closed shell then faces inward).
inline acd::TriangleMesh InsideOut(acd::TriangleMesh mesh) {
  mesh.triangles.col(1).swap(mesh.triangles.col(2));
  return mesh;
}

/// The shells `meshes` as one mesh, in order (several closed shells in one file).
inline acd::TriangleMesh Combined(const std::vector<acd::TriangleMesh>& meshes) {
  acd::TriangleMesh out;
  Eigen::Index vertices = 0, triangles = 0;
  for (const auto& m : meshes) {
    vertices += m.vertices.rows();
    triangles += m.triangles.rows();
  }
  out.vertices.resize(vertices, 3);
  out.triangles.resize(triangles, 3);
  vertices = triangles = 0;
  for (const auto& m : meshes) {
    out.vertices.middleRows(vertices, m.vertices.rows()) = m.vertices;
    out.triangles.middleRows(triangles, m.triangles.rows()) =
        (m.triangles.array() + static_cast<int>(vertices)).matrix();
    vertices += m.vertices.rows();
    triangles += m.triangles.rows();
  }
  return out;
}

/// Uniform SE(2) poses in `bounds`, seeded.
inline std::vector<Eigen::Isometry2d> RandomPoses2d(const Eigen::AlignedBox2d& bounds, int count,
                                                    std::uint64_t seed) {
  RandomEngine rng(seed);
  std::vector<Eigen::Isometry2d> poses;
  poses.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    // One draw per statement: the order of a call's arguments is unspecified.
    Eigen::Array2d unit;
    for (int k = 0; k < 2; ++k) unit[k] = UniformReal(rng, 0.0, 1.0);
    Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
    pose.translation() = bounds.min() + (bounds.sizes().array() * unit).matrix();
    pose.linear() = Eigen::Rotation2Dd(UniformReal(rng, -M_PI, M_PI)).toRotationMatrix();
    poses.push_back(pose);
  }
  return poses;
}

/// Uniform SE(3) poses in `bounds` (uniform rotations), seeded.
inline std::vector<Eigen::Isometry3d> RandomPoses3d(const Eigen::AlignedBox3d& bounds, int count,
                                                    std::uint64_t seed) {
  RandomEngine rng(seed);
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    // One draw per statement: the order of a call's arguments is unspecified.
    Eigen::Array3d unit;
    for (int k = 0; k < 3; ++k) unit[k] = UniformReal(rng, 0.0, 1.0);
    Eigen::Vector4d wxyz;
    for (int k = 0; k < 4; ++k) wxyz[k] = StandardNormal(rng);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = bounds.min() + (bounds.sizes().array() * unit).matrix();
    Eigen::Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
    pose.linear() = q.normalized().toRotationMatrix();
    poses.push_back(pose);
  }
  return poses;
}

/// A 3D world with `mesh` as its one obstacle, the bounds its box grown by 10% per side.
inline envs::Workspace3d MeshWorld(const acd::TriangleMesh& mesh) {
  envs::Workspace3d world;
  const Eigen::AlignedBox3d box = acd::BoundingBox(mesh);
  world.bounds = Eigen::AlignedBox3d(box.min() - 0.1 * box.sizes(), box.max() + 0.1 * box.sizes());
  world.obstacles.push_back(mesh);
  return world;
}

}  // namespace acdplan::collision::testing
