#include "collision/obstacle_set.h"

#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/decompose2d.h"
#include "acd/decompose3d.h"
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

namespace {

std::vector<Eigen::Vector3d> Points(const acd::TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    points.push_back(mesh.vertices.row(i).transpose());
  }
  return points;
}

/// The piece of `component` (index `c` in the set) with surface `solid`: its hull (thickened when
/// flat), planes, box and the component's triangles that may meet it.
ObstaclePiece MakePiece(const ObstacleComponent& component, int c, acd::TriangleMesh solid,
                        bool closed, bool repaired, double thickness) {
  ObstaclePiece piece;
  piece.obstacle = component.obstacle;
  piece.component = c;
  piece.closed = closed;
  piece.repaired = repaired;
  piece.hull = acd::ConvexHull3(Points(solid), thickness);
  piece.planes = acd::HullPlanes(piece.hull);
  for (Eigen::Index i = 0; i < piece.hull.vertices.rows(); ++i) {
    piece.box.extend(Eigen::Vector3d(piece.hull.vertices.row(i).transpose()));
  }
  piece.convex = closed && internal::EqualsItsHull(solid, piece.hull);
  // Grown by the thickness, so that rounding in the ACD's cut vertices cannot leave a component
  // triangle that touches the hull out of the confirmation set.
  const Eigen::AlignedBox3d grown(piece.box.min().array() - thickness,
                                  piece.box.max().array() + thickness);
  const acd::TriangleMesh& mesh = component.mesh;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    Eigen::AlignedBox3d box;
    for (int k = 0; k < 3; ++k)
      box.extend(Eigen::Vector3d(mesh.vertices.row(mesh.triangles(f, k))));
    if (box.intersects(grown)) piece.triangles.push_back(static_cast<int>(f));
  }
  piece.solid = std::move(solid);
  return piece;
}

/// How a component got its pieces (for hulls_source).
struct SourceCounts {
  int solid = 0, repaired = 0, surface = 0, hull_only = 0;
};

/// Decomposes component `c` of `set` and appends its pieces.
void AddComponentPieces(ObstacleSet* set, int c, double tau_rel, double thickness,
                        SourceCounts* counts) {
  const ObstacleComponent& component = set->components[static_cast<size_t>(c)];
  const std::string where =
      "obstacle " + std::to_string(component.obstacle) + ", part " + std::to_string(c);
  try {
    acd::PreparedMesh prepared = acd::PrepareMesh(component.mesh, {}, where);
    bool repaired = false;
    if (component.closed && !prepared.solid()) {
      // Closed but not a solid (self-intersecting): the repaired union's pieces cover the
      // volume inside the component, where the exact test may say "inside".
      prepared = acd::PrepareMesh(component.mesh, acd::PrepareMeshOptions{true}, where);
      if (!prepared.solid()) {
        throw std::runtime_error("not a solid even after repair: " + prepared.defects.first);
      }
      repaired = true;
    }
    acd::Decompose3dOptions options;
    options.tau = tau_rel * acd::ReferenceRadius(prepared.mesh);
    // An open component: the surface ACD (Decompose3d picks it for any non-solid input).
    const acd::Decomposition3d decomposition = acd::Decompose3d(prepared, options);
    if (decomposition.components.empty()) throw std::runtime_error("no component");
    const bool surface = decomposition.stats.surface;
    (surface ? counts->surface : repaired ? counts->repaired : counts->solid)++;
    for (const acd::Component3d& piece : decomposition.components) {
      set->pieces.push_back(MakePiece(component, c, piece.mesh, !surface, repaired, thickness));
    }
  } catch (const std::exception& error) {
    // Collision must not depend on the ACD succeeding: the component's hull covers it.
    ++counts->hull_only;
    set->notes.push_back(where + ": ACD did not run (" + error.what() +
                         "); its convex hull is its one piece");
    set->pieces.push_back(MakePiece(component, c, component.mesh, false, false, thickness));
  }
}

}  // namespace

ObstacleSet BuildObstacleSet(const envs::Workspace3d& workspace,
                             const ObstacleSetOptions& options) {
  if (!(options.tau_rel_3d > 0) || !std::isfinite(options.tau_rel_3d)) {
    throw InputError("BuildObstacleSet(): tau_rel_3d must be finite and > 0, got " +
                     std::to_string(options.tau_rel_3d));
  }
  ObstacleSet set;
  set.dimension = 3;
  set.bounds = workspace.bounds;
  set.extrusion_height = 0;
  const double thickness = 1e-6 * std::max(workspace.bounds.sizes().norm(), 1e-300);
  for (size_t k = 0; k < workspace.obstacles.size(); ++k) {
    acd::CheckTriangleMesh(workspace.obstacles[k],
                           "BuildObstacleSet(): obstacle " + std::to_string(k));
  }
  SourceCounts counts;
  for (size_t k = 0; k < workspace.obstacles.size(); ++k) {
    // Cleaned (vertices split at normal or UV seams welded, so the surface is not cut into
    // open pieces) and split into parts: solids with their cavities, or surface patches.
    acd::PreparedMesh prepared = acd::PrepareMesh(
        workspace.obstacles[k], {}, "BuildObstacleSet(): obstacle " + std::to_string(k));
    set.meshes.push_back(prepared.mesh);
    for (size_t p = 0; p < prepared.parts.size(); ++p) {
      ObstacleComponent component;
      component.obstacle = static_cast<int>(k);
      component.closed = prepared.closed_parts[p];
      component.mesh = std::move(prepared.parts[p]);
      set.components.push_back(std::move(component));
      AddComponentPieces(&set, static_cast<int>(set.components.size() - 1), options.tau_rel_3d,
                         thickness, &counts);
    }
  }
  std::ostringstream source;
  source << "ACD (Decompose3d, tau_rel = " << options.tau_rel_3d << ": " << counts.solid
         << " solid";
  if (counts.repaired > 0) source << ", " << counts.repaired << " solid after repair";
  source << ", " << counts.surface << " surface";
  if (counts.hull_only > 0) source << ", " << counts.hull_only << " plain hull";
  source << ")";
  set.hulls_source = source.str();
  return set;
}

int TriangleCount(const ObstacleSet& obstacles) {
  int count = 0;
  for (const auto& mesh : obstacles.meshes) count += static_cast<int>(mesh.triangles.rows());
  return count;
}

}  // namespace acdplan::collision
