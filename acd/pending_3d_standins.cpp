// TEMPORARY, branch io3d only: crude stand-ins for Decompose3d, ComponentGraph (engineer
// "solid") and CheckDecomposition3d (engineer "surface"), so that `acdplan decompose MESH` links
// and its tests run before those land. The integrator deletes this file (and its line in
// acd/CMakeLists.txt) when merging; io3d deletes it itself when it merges main with them.

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "acd/check_decomposition3d.h"
#include "acd/convex_hull3d.h"
#include "acd/decompose3d.h"
#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/stopwatch.h"

namespace acdplan::acd {

Decomposition3d Decompose3d(const PreparedMesh& prepared, const Decompose3dOptions& options) {
  if (!(options.tau >= 0) || !std::isfinite(options.tau)) {
    throw InputError("Decompose3d(): tau must be a finite number >= 0, got " +
                     FormatSignificant(options.tau, 15));
  }
  const Stopwatch watch;
  Decomposition3d d;
  d.tau = options.tau;
  d.max_hulls = options.max_hulls;
  const bool surface = options.surface || !prepared.solid();
  for (size_t p = 0; p < prepared.parts.size(); ++p) {
    Component3d c;
    c.mesh = prepared.parts[p];
    std::vector<Eigen::Vector3d> points;
    for (Eigen::Index i = 0; i < c.mesh.vertices.rows(); ++i) {
      points.push_back(c.mesh.vertices.row(i).transpose());
    }
    c.hull = ConvexHull3(points, 0.0);
    c.volume = surface ? 0.0 : MeshVolume(c.mesh);
    c.hull_volume = MeshVolume(c.hull);
    c.centroid = MeshCentroid(c.mesh, !surface);
    c.source = static_cast<int>(p);
    HierarchyNode3d node;
    node.component = static_cast<int>(d.components.size());
    d.roots.push_back(static_cast<int>(d.tree.size()));
    d.tree.push_back(node);
    d.stats.volume += c.volume;
    d.stats.hull_volume += c.hull_volume;
    d.components.push_back(std::move(c));
  }
  d.stats.vertices = static_cast<int>(prepared.mesh.vertices.rows());
  d.stats.triangles = static_cast<int>(prepared.mesh.triangles.rows());
  d.stats.components = static_cast<int>(d.components.size());
  d.stats.surface = surface;
  d.stats.time_ms = watch.Milliseconds();
  return d;
}

std::vector<std::vector<int>> ComponentGraph(const Decomposition3d& decomposition) {
  std::vector<std::set<int>> sets(decomposition.components.size());
  for (const Opening3d& o : decomposition.openings) {
    sets.at(o.component_a).insert(o.component_b);
    sets.at(o.component_b).insert(o.component_a);
  }
  std::vector<std::vector<int>> graph;
  for (const std::set<int>& s : sets) graph.emplace_back(s.begin(), s.end());
  return graph;
}

DecompositionCheck CheckDecomposition3d(const PreparedMesh&, const Decomposition3d&) { return {}; }

}  // namespace acdplan::acd
