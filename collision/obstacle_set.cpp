#include "collision/obstacle_set.h"

#include <cmath>
#include <sstream>

#include "acd/convex_hull3d.h"
#include "acd/decompose2d.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"
#include "collision/internal/mesh_building.h"

namespace acdplan::collision {

ObstacleSet BuildObstacleSet(const envs::Workspace2d& workspace,
                             const ObstacleSetOptions& options) {
  if (!(options.tau >= 0) || !std::isfinite(options.tau)) {
    throw InputError("BuildObstacleSet(): tau must be finite and >= 0, got " +
                     std::to_string(options.tau));
  }
  if (!(options.extrusion_height > 0) || !std::isfinite(options.extrusion_height)) {
    throw InputError("BuildObstacleSet(): extrusion_height must be finite and > 0, got " +
                     std::to_string(options.extrusion_height));
  }
  const double h = options.extrusion_height;
  ObstacleSet set;
  set.dimension = 2;
  set.extrusion_height = h;
  set.bounds = Eigen::AlignedBox3d(
      Eigen::Vector3d(workspace.bounds.min().x(), workspace.bounds.min().y(), -h / 2),
      Eigen::Vector3d(workspace.bounds.max().x(), workspace.bounds.max().y(), h / 2));
  std::ostringstream source;
  source << "ACD (Decompose2d, tau = " << options.tau << ")";
  set.hulls_source = source.str();

  acd::Decompose2dOptions decompose;
  decompose.tau = options.tau;
  for (size_t k = 0; k < workspace.obstacles.size(); ++k) {
    const acd::Polygon2d& obstacle = workspace.obstacles[k];
    set.polygons.push_back(obstacle);
    set.meshes.push_back(internal::ExtrudePolygon(obstacle, -h / 2, h / 2));
    // The obstacle itself is the solid here (Ch. VI.A: "solid ACD"), not the free space.
    const acd::Decomposition2d decomposition = acd::Decompose2d(obstacle, decompose);
    for (const acd::Component2d& component : decomposition.components) {
      ObstaclePiece piece;
      piece.obstacle = static_cast<int>(k);
      piece.polygon = component.polygon;
      piece.solid = internal::ExtrudePolygon(component.polygon, -h / 2, h / 2);
      piece.closed = true;
      piece.convex = component.polygon.holes.empty() &&
                     component.hull.size() == component.polygon.outer.size();
      piece.hull = internal::ExtrudeConvexRing(component.hull, -h / 2, h / 2);
      piece.planes = acd::HullPlanes(piece.hull);
      for (Eigen::Index i = 0; i < piece.hull.vertices.rows(); ++i) {
        piece.box.extend(Eigen::Vector3d(piece.hull.vertices.row(i).transpose()));
      }
      set.pieces.push_back(std::move(piece));
    }
  }
  return set;
}

ObstacleSet BuildObstacleSet(const envs::Workspace3d& workspace) {
  ObstacleSet set;
  set.dimension = 3;
  set.bounds = workspace.bounds;
  set.extrusion_height = 0;
  set.hulls_source = "connected components (no 3D ACD yet)";
  const double thickness = 1e-6 * std::max(workspace.bounds.sizes().norm(), 1e-300);
  for (size_t k = 0; k < workspace.obstacles.size(); ++k) {
    acd::CheckTriangleMesh(workspace.obstacles[k],
                           "BuildObstacleSet(): obstacle " + std::to_string(k));
    // Cleaned (vertices split at normal or UV seams welded, so the surface is not cut into
    // open pieces) and split into parts: solids with their cavities, or surface patches.
    acd::PreparedMesh prepared = acd::PrepareMesh(
        workspace.obstacles[k], {}, "BuildObstacleSet(): obstacle " + std::to_string(k));
    set.meshes.push_back(prepared.mesh);
    for (size_t p = 0; p < prepared.parts.size(); ++p) {
      acd::TriangleMesh& component = prepared.parts[p];
      ObstaclePiece piece;
      piece.obstacle = static_cast<int>(k);
      piece.closed = prepared.closed_parts[p];
      std::vector<Eigen::Vector3d> points;
      for (Eigen::Index i = 0; i < component.vertices.rows(); ++i) {
        points.push_back(component.vertices.row(i).transpose());
      }
      piece.hull = acd::ConvexHull3(points, thickness);
      piece.planes = acd::HullPlanes(piece.hull);
      for (Eigen::Index i = 0; i < piece.hull.vertices.rows(); ++i) {
        piece.box.extend(Eigen::Vector3d(piece.hull.vertices.row(i).transpose()));
      }
      piece.solid = std::move(component);
      set.pieces.push_back(std::move(piece));
    }
  }
  return set;
}

int TriangleCount(const ObstacleSet& obstacles) {
  int count = 0;
  for (const auto& mesh : obstacles.meshes) count += static_cast<int>(mesh.triangles.rows());
  return count;
}

}  // namespace acdplan::collision
