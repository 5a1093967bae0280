#include "acd/decompose3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include "acd/convex_hull3d.h"
#include "acd/internal/solid_acd.h"
#include "acd/internal/solid_concavity.h"
#include "acd/internal/solid_openings.h"
#include "acd/internal/surface_acd.h"
#include "acd/mesh_measures.h"
#include "base/input_error.h"
#include "base/stopwatch.h"

namespace acdplan::acd {
namespace {

void ValidateOptions(const Decompose3dOptions& options, const PreparedMesh& prepared) {
  auto fail = [](const std::string& what) { throw InputError("Decompose3d(): " + what); };
  if (!(options.tau >= 0.0) || !std::isfinite(options.tau)) {
    std::ostringstream s;
    s << "tau must be a finite number >= 0, got " << options.tau;
    fail(s.str());
  }
  if (options.max_hulls < 0) {
    fail("max_hulls must be >= 0 (0 = no cap), got " + std::to_string(options.max_hulls));
  }
  if (prepared.parts.empty()) fail("the prepared mesh has no part (run PrepareMesh first)");
}

// The union of two or more solids that share cut faces: vertices welded by position, and each
// face met back to back by its reverse (the shared cap) dropped.
TriangleMesh JoinSolids(const std::vector<const TriangleMesh*>& meshes) {
  std::map<std::tuple<double, double, double>, int> index;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (const TriangleMesh* m : meshes) {
    std::vector<int> id(static_cast<size_t>(m->vertices.rows()));
    for (Eigen::Index i = 0; i < m->vertices.rows(); ++i) {
      const auto key = std::make_tuple(m->vertices(i, 0), m->vertices(i, 1), m->vertices(i, 2));
      auto [it, inserted] = index.emplace(key, static_cast<int>(vertices.size()));
      if (inserted) vertices.emplace_back(m->vertices.row(i));
      id[static_cast<size_t>(i)] = it->second;
    }
    for (Eigen::Index f = 0; f < m->triangles.rows(); ++f) {
      triangles.push_back({id[static_cast<size_t>(m->triangles(f, 0))], id[static_cast<size_t>(m->triangles(f, 1))],
                           id[static_cast<size_t>(m->triangles(f, 2))]});
    }
  }
  // A face and its reverse rotate to the same sorted triple with opposite parity.
  auto canonical = [](std::array<int, 3> t) {
    const int k = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
    std::rotate(t.begin(), t.begin() + k, t.end());
    return t;
  };
  std::map<std::array<int, 3>, std::vector<size_t>> by_face;
  for (size_t f = 0; f < triangles.size(); ++f) by_face[canonical(triangles[f])].push_back(f);
  std::vector<char> drop(triangles.size(), 0);
  for (size_t f = 0; f < triangles.size(); ++f) {
    if (drop[f]) continue;
    const std::array<int, 3> c = canonical(triangles[f]);
    auto it = by_face.find({c[0], c[2], c[1]});
    if (it == by_face.end()) continue;
    for (size_t g : it->second) {
      if (!drop[g]) {
        drop[f] = drop[g] = 1;
        break;
      }
    }
  }
  std::vector<Eigen::Vector3i> kept;
  for (size_t f = 0; f < triangles.size(); ++f) {
    if (!drop[f]) kept.emplace_back(triangles[f][0], triangles[f][1], triangles[f][2]);
  }
  // Drop the vertices only the shared caps used.
  std::vector<int> remap(vertices.size(), -1);
  std::vector<Eigen::Vector3d> used;
  for (auto& t : kept) {
    for (int k = 0; k < 3; ++k) {
      int& r = remap[static_cast<size_t>(t(k))];
      if (r < 0) r = static_cast<int>(used.size()), used.push_back(vertices[static_cast<size_t>(t(k))]);
      t(k) = r;
    }
  }
  return MakeTriangleMesh(used, kept);
}

// The max_hulls cap on a solid decomposition: walks the hierarchy back up (its levels of
// detail, Fig. 9), each time collapsing the internal node whose children are all leaves and
// whose merged hull adds the least volume over its children's hulls, until at most
// `max_hulls` components remain (or only roots do). The merged component is the exact union
// of its children (they share the node's cap faces), re-measured.
void CapHulls(int max_hulls, double tau, Decomposition3d* d) {
  if (max_hulls <= 0) return;
  int count = static_cast<int>(d->components.size());
  std::vector<Component3d> comps = std::move(d->components);
  while (count > max_hulls) {
    int best = -1;
    double best_added = std::numeric_limits<double>::infinity();
    TriangleMesh best_mesh, best_hull;
    for (size_t x = 0; x < d->tree.size(); ++x) {
      const HierarchyNode3d& node = d->tree[x];
      if (node.children.empty() || node.component >= 0) continue;
      bool all_leaves = true;
      for (int c : node.children) all_leaves = all_leaves && d->tree[static_cast<size_t>(c)].component >= 0;
      if (!all_leaves) continue;
      std::vector<const TriangleMesh*> meshes;
      double children_hulls = 0;
      for (int c : node.children) {
        const Component3d& comp = comps[static_cast<size_t>(d->tree[static_cast<size_t>(c)].component)];
        meshes.push_back(&comp.mesh);
        children_hulls += comp.hull_volume;
      }
      TriangleMesh merged = JoinSolids(meshes);
      std::vector<Eigen::Vector3d> points;
      for (Eigen::Index i = 0; i < merged.vertices.rows(); ++i) points.emplace_back(merged.vertices.row(i));
      TriangleMesh hull = ConvexHull3(points, 0.0);
      const double added = MeshVolume(hull) - children_hulls;
      if (added < best_added) {
        best_added = added;
        best = static_cast<int>(x);
        best_mesh = std::move(merged);
        best_hull = std::move(hull);
      }
    }
    if (best < 0) break;
    HierarchyNode3d& node = d->tree[static_cast<size_t>(best)];
    Component3d merged;
    merged.source = comps[static_cast<size_t>(d->tree[static_cast<size_t>(node.children[0])].component)].source;
    for (int c : node.children) {
      comps[static_cast<size_t>(d->tree[static_cast<size_t>(c)].component)].mesh = {};  // retired
      d->tree[static_cast<size_t>(c)].component = -1;
    }
    merged.mesh = std::move(best_mesh);
    merged.hull = std::move(best_hull);
    merged.volume = MeshVolume(merged.mesh);
    merged.hull_volume = MeshVolume(merged.hull);
    merged.centroid = MeshCentroid(merged.mesh, true);
    merged.concavity = internal::MeasureSolidConcavity(merged.mesh, tau).value;
    node.concavity = merged.concavity;
    node.component = static_cast<int>(comps.size());
    comps.push_back(std::move(merged));
    count -= static_cast<int>(node.children.size()) - 1;
  }
  // Keep only the nodes still reachable, renumbered, and the leaves in depth-first order.
  std::vector<HierarchyNode3d> tree;
  std::vector<int> roots;
  d->components.clear();
  for (int root : d->roots) {
    std::vector<std::pair<int, int>> stack = {{root, -1}};  // (old node, new parent)
    while (!stack.empty()) {
      const auto [x, parent] = stack.back();
      stack.pop_back();
      HierarchyNode3d node = d->tree[static_cast<size_t>(x)];
      const int id = static_cast<int>(tree.size());
      const std::vector<int> children = node.component >= 0 ? std::vector<int>{} : node.children;
      node.children.clear();
      node.parent = parent;
      if (parent >= 0) tree[static_cast<size_t>(parent)].children.push_back(id);
      else roots.push_back(id);
      if (node.component >= 0) {
        Component3d& c = comps[static_cast<size_t>(node.component)];
        node.component = static_cast<int>(d->components.size());
        node.cut = Plane3d{};
        d->components.push_back(std::move(c));
      }
      tree.push_back(node);
      for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, id);
    }
  }
  d->tree = std::move(tree);
  d->roots = std::move(roots);
  internal::ComputeOpenings(d);
  d->stats.components = static_cast<int>(d->components.size());
  d->stats.volume = d->stats.hull_volume = d->stats.max_concavity = 0.0;
  for (const Component3d& c : d->components) {
    d->stats.volume += c.volume;
    d->stats.hull_volume += c.hull_volume;
    d->stats.max_concavity = std::max(d->stats.max_concavity, c.concavity);
  }
}

}  // namespace

Decomposition3d Decompose3d(const PreparedMesh& prepared, const Decompose3dOptions& options) {
  ValidateOptions(options, prepared);
  const Stopwatch watch;
  const bool surface = options.surface || !prepared.solid();
  Decomposition3d out = surface ? internal::DecomposeSurface(prepared, options.tau)
                                : internal::DecomposeSolid(prepared, options.tau);
  out.tau = options.tau;
  out.max_hulls = options.max_hulls;
  if (!surface) CapHulls(options.max_hulls, options.tau, &out);
  out.stats.surface = surface;
  out.stats.time_ms = watch.Milliseconds();
  return out;
}

}  // namespace acdplan::acd
