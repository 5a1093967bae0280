#include "acd/internal/feature_grouping.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <utility>

#include "acd/internal/mesh_edges.h"

namespace acdplan::acd::internal {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Eigen::Vector3d Position(const TriangleMesh& mesh, int v) { return mesh.vertices.row(v); }

Eigen::Vector3d FaceNormal(const TriangleMesh& mesh, int f) {
  const Eigen::Vector3d a = Position(mesh, mesh.triangles(f, 0));
  const Eigen::Vector3d b = Position(mesh, mesh.triangles(f, 1));
  const Eigen::Vector3d c = Position(mesh, mesh.triangles(f, 2));
  return (b - a).cross(c - a).normalized();
}

// The vertex-edge graph of a mesh: per vertex, (neighbour, edge index) sorted by neighbour.
struct EdgeGraph {
  EdgeTable table;
  std::vector<std::vector<std::pair<int, int>>> adjacent;
};

EdgeGraph BuildEdgeGraph(const TriangleMesh& mesh) {
  EdgeGraph graph;
  graph.table = BuildEdgeTable(mesh);
  graph.adjacent.resize(static_cast<size_t>(mesh.vertices.rows()));
  for (size_t e = 0; e < graph.table.edges.size(); ++e) {
    const MeshEdge& edge = graph.table.edges[e];
    graph.adjacent[static_cast<size_t>(edge.a)].emplace_back(edge.b, static_cast<int>(e));
    graph.adjacent[static_cast<size_t>(edge.b)].emplace_back(edge.a, static_cast<int>(e));
  }
  for (auto& list : graph.adjacent) std::sort(list.begin(), list.end());
  return graph;
}

// The index of edge u-v in `table`, or -1.
int FindEdge(const EdgeTable& table, int u, int v) {
  const int a = std::min(u, v), b = std::max(u, v);
  const auto it = std::lower_bound(table.edges.begin(), table.edges.end(), std::make_pair(a, b),
                                   [](const MeshEdge& e, const std::pair<int, int>& key) {
                                     return std::make_pair(e.a, e.b) < key;
                                   });
  if (it == table.edges.end() || it->a != a || it->b != b) return -1;
  return static_cast<int>(it - table.edges.begin());
}

struct ShortestPaths {
  std::vector<double> distance;
  std::vector<int> parent;  // -1 at the source and where unreached
};

// Dijkstra from `source` over the edges `usable(edge)` with costs `cost(edge)`; a vertex for
// which `passable(vertex)` is false can be reached but not left (the source can always be
// left). Ties go to the smaller vertex, so the result is deterministic.
template <typename Usable, typename Cost, typename Passable>
ShortestPaths Dijkstra(const EdgeGraph& graph, int source, Usable usable, Cost cost,
                       Passable passable) {
  const size_t n = graph.adjacent.size();
  ShortestPaths out;
  out.distance.assign(n, kInfinity);
  out.parent.assign(n, -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  out.distance[static_cast<size_t>(source)] = 0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > out.distance[static_cast<size_t>(u)]) continue;
    if (u != source && !passable(u)) continue;
    for (const auto& [v, e] : graph.adjacent[static_cast<size_t>(u)]) {
      if (!usable(e)) continue;
      const double next = d + cost(e);
      if (next < out.distance[static_cast<size_t>(v)]) {
        out.distance[static_cast<size_t>(v)] = next;
        out.parent[static_cast<size_t>(v)] = u;
        queue.emplace(next, v);
      }
    }
  }
  return out;
}

// The path from the source of `paths` to `target` (source first), or empty if unreached.
std::vector<int> PathTo(const ShortestPaths& paths, int target) {
  std::vector<int> path;
  if (paths.distance[static_cast<size_t>(target)] == kInfinity) return path;
  for (int v = target; v >= 0; v = paths.parent[static_cast<size_t>(v)]) path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

// The signed exterior dihedral angle of edge `e` (> 0 convex, < 0 reflex, 0 flat or open).
double DihedralAngle(const TriangleMesh& mesh, const EdgeTable& table, int e) {
  const MeshEdge& edge = table.edges[static_cast<size_t>(e)];
  if (edge.count != 2) return 0.0;
  const int f1 = table.faces[static_cast<size_t>(edge.first)];
  const int f2 = table.faces[static_cast<size_t>(edge.first) + 1];
  const Eigen::Vector3d n1 = FaceNormal(mesh, f1), n2 = FaceNormal(mesh, f2);
  const double angle = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
  int opposite = mesh.triangles(f2, 0);
  for (int k = 0; k < 3; ++k) {
    const int v = mesh.triangles(f2, k);
    if (v != edge.a && v != edge.b) opposite = v;
  }
  const bool convex = n1.dot(Position(mesh, opposite) - Position(mesh, edge.a)) < 0;
  return convex ? angle : -angle;
}

// Step 5 of FindGlobalCuts(): the least-squares plane of the cycle's vertices, each weighted
// by (concavity + delta) x half its two edges' lengths. False if the cycle is (nearly) a line.
bool FitCyclePlane(const TriangleMesh& mesh, const std::vector<int>& cycle,
                   const std::vector<double>& c, double delta, Plane3d* plane) {
  const size_t m = cycle.size();
  std::vector<double> weights(m);
  double total = 0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d p = Position(mesh, cycle[i]);
    const double half = 0.5 * ((p - Position(mesh, cycle[(i + m - 1) % m])).norm() +
                               (p - Position(mesh, cycle[(i + 1) % m])).norm());
    weights[i] = (c[static_cast<size_t>(cycle[i])] + delta) * half;
    total += weights[i];
    mean += weights[i] * p;
  }
  if (!(total > 0)) return false;
  mean /= total;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d d = Position(mesh, cycle[i]) - mean;
    cov += weights[i] * d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d values = eig.eigenvalues();                        // ascending
  if (!(values(2) > 0) || !(values(1) > 1e-12 * values(2))) return false;  // collinear
  Eigen::Vector3d normal = eig.eigenvectors().col(0).normalized();
  for (int k = 0; k < 3; ++k) {  // one sign per direction
    if (std::abs(normal(k)) > 1e-12) {
      if (normal(k) < 0) normal = -normal;
      break;
    }
  }
  plane->normal = normal;
  plane->offset = normal.dot(mean);
  return true;
}

}  // namespace

std::vector<int> DouglasPeucker(const std::vector<Eigen::Vector2d>& chain, double delta) {
  const int n = static_cast<int>(chain.size());
  if (n <= 2) {
    std::vector<int> all(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) all[static_cast<size_t>(i)] = i;
    return all;
  }
  std::vector<char> keep(static_cast<size_t>(n), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<int, int>> stack = {{0, n - 1}};
  while (!stack.empty()) {
    const auto [first, last] = stack.back();
    stack.pop_back();
    if (last - first < 2) continue;
    const Eigen::Vector2d a = chain[static_cast<size_t>(first)];
    const Eigen::Vector2d ab = chain[static_cast<size_t>(last)] - a;
    const double len = ab.norm();
    int far = -1;
    double far_distance = -1;
    for (int i = first + 1; i < last; ++i) {
      const Eigen::Vector2d ap = chain[static_cast<size_t>(i)] - a;
      const double d = len > 0 ? std::abs(ab.x() * ap.y() - ab.y() * ap.x()) / len : ap.norm();
      if (d > far_distance) far_distance = d, far = i;
    }
    if (far_distance > delta) {  // Algorithm 7, line 2
      keep[static_cast<size_t>(far)] = 1;
      stack.emplace_back(far, last);
      stack.emplace_back(first, far);
    }
  }
  std::vector<int> kept;
  for (int i = 0; i < n; ++i) {
    if (keep[static_cast<size_t>(i)]) kept.push_back(i);
  }
  return kept;
}

std::vector<std::vector<int>> PocketBorderLoops(const TriangleMesh& mesh,
                                                const std::vector<int>& face_pocket, int pocket) {
  // Border half-edges a -> b along the pocket faces' orientation, whose twin face is elsewhere.
  const EdgeTable table = BuildEdgeTable(mesh);
  std::map<int, std::vector<int>> outgoing;  // a -> the b's, ascending
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    if (face_pocket[static_cast<size_t>(f)] != pocket) continue;
    for (int k = 0; k < 3; ++k) {
      const MeshEdge& edge =
          table.edges[static_cast<size_t>(table.face_edges[static_cast<size_t>(f)][k])];
      int inside = 0;
      for (int i = 0; i < edge.count; ++i) {
        inside +=
            face_pocket[static_cast<size_t>(table.faces[static_cast<size_t>(edge.first + i)])] ==
            pocket;
      }
      if (inside == 1) {
        outgoing[mesh.triangles(f, k)].push_back(mesh.triangles(f, (k + 1) % 3));
      }
    }
  }
  for (auto& [a, list] : outgoing) std::sort(list.begin(), list.end());
  std::vector<std::vector<int>> loops;
  for (auto& [start, list] : outgoing) {
    while (!list.empty()) {
      std::vector<int> loop = {start};
      int at = start;
      while (true) {
        std::vector<int>& next = outgoing[at];
        if (next.empty()) break;  // not closed (cannot happen on a closed mesh)
        const int to = next.front();
        next.erase(next.begin());
        if (to == start) break;
        loop.push_back(to);
        at = to;
      }
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

std::vector<int> FindKnots(const TriangleMesh& mesh, const std::vector<int>& loop,
                           const std::vector<double>& concavity, double delta) {
  const size_t n = loop.size();
  if (n < 3) return {};
  // Open the loop at its least concave vertex (the first on ties), and close it back there.
  size_t start = 0;
  for (size_t i = 1; i < n; ++i) {
    if (concavity[static_cast<size_t>(loop[i])] < concavity[static_cast<size_t>(loop[start])])
      start = i;
  }
  std::vector<int> order;
  std::vector<Eigen::Vector2d> chain;  // Eq. 5.1: (arc length, concavity)
  double s = 0;
  for (size_t i = 0; i <= n; ++i) {
    const int v = loop[(start + i) % n];
    if (i > 0) s += (Position(mesh, v) - Position(mesh, order.back())).norm();
    order.push_back(v);
    chain.emplace_back(s, concavity[static_cast<size_t>(v)]);
  }
  const std::vector<int> kept = DouglasPeucker(chain, delta);
  std::vector<int> knots;
  for (size_t k = 1; k + 1 < kept.size(); ++k) {
    const Eigen::Vector2d& p = chain[static_cast<size_t>(kept[k - 1])];
    const Eigen::Vector2d& q = chain[static_cast<size_t>(kept[k])];
    const Eigen::Vector2d& r = chain[static_cast<size_t>(kept[k + 1])];
    const double turn = (q - p).x() * (r - q).y() - (q - p).y() * (r - q).x();
    if (turn < 0 && q.y() > delta) knots.push_back(order[static_cast<size_t>(kept[k])]);
  }
  return knots;
}

std::vector<GlobalCut> FindGlobalCuts(const TriangleMesh& mesh, const SolidConcavity& concavity,
                                      double tau, const FeatureGroupingOptions& options) {
  GlobalCut common;  // what every cut of this piece shares: the knots, the cup flag
  const int pocket = concavity.witness_pocket;
  const size_t nv = static_cast<size_t>(mesh.vertices.rows());
  if (pocket < 0 || !(tau > 0) || concavity.vertex_concavity.size() != nv ||
      concavity.face_pocket.size() != static_cast<size_t>(mesh.triangles.rows())) {
    return {};
  }
  const std::vector<double>& c = concavity.vertex_concavity;
  const std::vector<int>& face_pocket = concavity.face_pocket;
  const double delta = options.delta_fraction * tau;
  // The witness vertex: the deepest corner of the witness face when a face sample won.
  int x = concavity.witness_vertex;
  if (x < 0) {
    if (concavity.witness_face < 0) return {};
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(concavity.witness_face, k);
      if (x < 0 || c[static_cast<size_t>(v)] > c[static_cast<size_t>(x)] ||
          (c[static_cast<size_t>(v)] == c[static_cast<size_t>(x)] && v < x))
        x = v;
    }
  }
  // 1. Knots on the pocket's border loops, the deepest max_knots kept.
  const std::vector<std::vector<int>> loops = PocketBorderLoops(mesh, face_pocket, pocket);
  if (loops.empty()) return {};
  std::vector<char> on_border(nv, 0);
  for (const auto& loop : loops) {
    for (int v : loop) on_border[static_cast<size_t>(v)] = 1;
    for (int v : FindKnots(mesh, loop, c, delta)) common.knots.push_back(v);
  }
  std::sort(common.knots.begin(), common.knots.end());
  common.knots.erase(std::unique(common.knots.begin(), common.knots.end()), common.knots.end());
  std::stable_sort(common.knots.begin(), common.knots.end(), [&](int a, int b) {
    return c[static_cast<size_t>(a)] > c[static_cast<size_t>(b)];
  });
  if (static_cast<int>(common.knots.size()) > options.max_knots)
    common.knots.resize(static_cast<size_t>(std::max(options.max_knots, 2)));
  common.cup = std::find(common.knots.begin(), common.knots.end(), x) == common.knots.end();
  std::vector<int> ends = common.knots;
  if (on_border[static_cast<size_t>(x)] && common.cup) ends.push_back(x);
  if (ends.size() < 2) {  // no knot pair: each loop's start and its farthest vertex
    for (const auto& loop : loops) {
      int far = loop.front();
      double far_distance = -1;
      for (int v : loop) {
        const double d = (Position(mesh, v) - Position(mesh, loop.front())).squaredNorm();
        if (d > far_distance) far_distance = d, far = v;
      }
      for (int v : {loop.front(), far}) {
        if (std::find(ends.begin(), ends.end(), v) == ends.end()) {
          ends.push_back(v);
          common.knots.push_back(v);
        }
      }
    }
  }
  if (ends.size() < 2) return {};

  const EdgeGraph graph = BuildEdgeGraph(mesh);
  const EdgeTable& table = graph.table;
  std::vector<char> in_pocket(nv, 0);
  for (size_t f = 0; f < face_pocket.size(); ++f) {
    if (face_pocket[f] != pocket) continue;
    for (int k = 0; k < 3; ++k) in_pocket[static_cast<size_t>(mesh.triangles(f, k))] = 1;
  }
  std::vector<int> pocket_faces(table.edges.size(), 0);  // faces of the pocket on each edge
  for (size_t e = 0; e < table.edges.size(); ++e) {
    const MeshEdge& edge = table.edges[e];
    for (int i = 0; i < edge.count; ++i) {
      pocket_faces[e] +=
          face_pocket[static_cast<size_t>(table.faces[static_cast<size_t>(edge.first + i)])] ==
          pocket;
    }
  }
  double c_max = 0;
  for (double v : c) c_max = std::max(c_max, v);
  const double scale = c_max + delta;
  auto length = [&](int e) {
    const MeshEdge& edge = table.edges[static_cast<size_t>(e)];
    return (Position(mesh, edge.a) - Position(mesh, edge.b)).norm();
  };
  auto cost = [&](int e) {
    const MeshEdge& edge = table.edges[static_cast<size_t>(e)];
    const double mean = 0.5 * (c[static_cast<size_t>(edge.a)] + c[static_cast<size_t>(edge.b)]);
    return length(e) * (scale - std::clamp(mean, 0.0, c_max)) / scale;
  };
  // 2. Pocket cuts from the witness to the ends, through the pocket.
  const ShortestPaths inner = Dijkstra(
      graph, x, [&](int e) { return pocket_faces[static_cast<size_t>(e)] == 2; }, cost,
      [](int) { return true; });
  // 3. Closing paths from each end around the rest of the surface.
  std::vector<ShortestPaths> outer;
  for (int end : ends) {
    outer.push_back(Dijkstra(
        graph, end, [&](int e) { return pocket_faces[static_cast<size_t>(e)] == 0; }, cost,
        [&](int v) { return !in_pocket[static_cast<size_t>(v)]; }));
  }
  // 4. The lightest cycle.
  auto weight = [&](const std::vector<int>& cycle) {
    double sum = 0, gamma = 0;
    for (size_t i = 0; i < cycle.size(); ++i) {
      sum += c[static_cast<size_t>(cycle[i])];
      const int e = FindEdge(table, cycle[i], cycle[(i + 1) % cycle.size()]);
      if (e < 0) return kInfinity;
      gamma += length(e) * (1 + DihedralAngle(mesh, table, e) / M_PI);
    }
    if (!(sum > 0)) return kInfinity;
    return static_cast<double>(cycle.size()) / sum * gamma;
  };
  struct Cycle {
    double weight;
    std::vector<int> vertices;
    int root_length;
  };
  std::vector<Cycle> cycles;
  for (size_t i = 0; i < ends.size(); ++i) {
    const std::vector<int> to_a = PathTo(inner, ends[i]);
    if (to_a.empty()) continue;
    for (size_t j = 0; j < ends.size(); ++j) {
      if (i == j) continue;
      const std::vector<int> to_b = PathTo(inner, ends[j]);
      if (to_b.empty()) continue;
      // The two halves must leave the witness apart (or one is the witness itself).
      if (to_a.size() > 1 && to_b.size() > 1 && to_a[1] == to_b[1]) continue;
      const std::vector<int> closing = PathTo(outer[j], ends[i]);  // b ... a
      if (closing.size() < 2) continue;
      std::vector<int> cycle(to_a.rbegin(), to_a.rend());  // a ... x
      cycle.insert(cycle.end(), to_b.begin() + 1, to_b.end());
      const int root_length = static_cast<int>(cycle.size());
      cycle.insert(cycle.end(), closing.begin() + 1, closing.end() - 1);
      if (cycle.size() < 3) continue;
      const double w = weight(cycle);
      if (w < kInfinity) cycles.push_back({w, std::move(cycle), root_length});
    }
  }
  std::stable_sort(cycles.begin(), cycles.end(),
                   [](const Cycle& a, const Cycle& b) { return a.weight < b.weight; });
  std::vector<GlobalCut> out;
  for (const Cycle& cycle : cycles) {
    if (static_cast<int>(out.size()) >= options.max_cuts) break;
    Plane3d plane;
    if (!FitCyclePlane(mesh, cycle.vertices, c, delta, &plane)) continue;
    bool repeated = false;  // (a, b) and (b, a) often close the same way
    for (const GlobalCut& kept : out) {
      repeated = repeated || (kept.plane.normal.dot(plane.normal) > 1 - 1e-9 &&
                              std::abs(kept.plane.offset - plane.offset) <= 1e-9 * (1 + c_max));
    }
    if (repeated) continue;
    GlobalCut cut = common;
    cut.found = true;
    cut.cycle = cycle.vertices;
    cut.root_cut_length = cycle.root_length;
    cut.weight = cycle.weight;
    cut.plane = plane;
    out.push_back(std::move(cut));
  }
  return out;
}

GlobalCut FindGlobalCut(const TriangleMesh& mesh, const SolidConcavity& concavity, double tau,
                        const FeatureGroupingOptions& options) {
  FeatureGroupingOptions one = options;
  one.max_cuts = 1;
  std::vector<GlobalCut> cuts = FindGlobalCuts(mesh, concavity, tau, one);
  return cuts.empty() ? GlobalCut{} : std::move(cuts.front());
}

}  // namespace acdplan::acd::internal
