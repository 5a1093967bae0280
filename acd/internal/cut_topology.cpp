#include "acd/internal/cut_topology.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "acd/internal/disjoint_sets.h"

namespace acdplan::acd::internal {
namespace {

// A bound on the rounding error of a height n . p - offset computed in doubles, relative to
// sum |n_k| max |p_k| + |offset| (a few units in the last place, with a wide margin).
constexpr double kHeightError = 1e-14;

}  // namespace

std::optional<CutTopology> PredictCutTopology(const TriangleMesh& mesh, int genus,
                                              const Plane3d& plane) {
  const int n = static_cast<int>(mesh.vertices.rows());
  if (n == 0) return std::nullopt;
  Eigen::VectorXd height = mesh.vertices * plane.normal;
  height.array() -= plane.offset;
  const double error =
      kHeightError *
      (plane.normal.cwiseAbs().dot(mesh.vertices.cwiseAbs().colwise().maxCoeff().transpose()) +
       std::abs(plane.offset));
  // A vertex whose height's sign is uncertain may lie in the plane, and the exact cut then puts
  // it in the section. Counting it above gives the same topology unless the sign changes more
  // than twice around it, or around a connected cluster of such vertices (a saddle: the section
  // pinches there), or a face has three (it lies in the plane); then there is no prediction.
  std::vector<char> uncertain(static_cast<size_t>(n), 0);
  bool any_uncertain = false;
  for (int v = 0; v < n; ++v) {
    if (std::abs(height(v)) <= error) uncertain[static_cast<size_t>(v)] = 1, any_uncertain = true;
  }
  if (any_uncertain) {
    DisjointSets clusters(n);
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
        if (uncertain[static_cast<size_t>(a)] && uncertain[static_cast<size_t>(b)]) {
          clusters.Unite(a, b);
        }
      }
    }
    std::vector<int> changes(static_cast<size_t>(n), 0);  // per cluster, at its root
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      int count = 0, at = 0;
      for (int k = 0; k < 3; ++k) {
        if (uncertain[static_cast<size_t>(mesh.triangles(f, k))]) ++count, at = k;
      }
      if (count == 3) return std::nullopt;
      if (count != 1) continue;  // the link of a cluster: the far edges of its faces
      const int a = mesh.triangles(f, (at + 1) % 3), b = mesh.triangles(f, (at + 2) % 3);
      if ((height(a) > 0) != (height(b) > 0) &&
          ++changes[static_cast<size_t>(clusters.Find(mesh.triangles(f, at)))] > 2) {
        return std::nullopt;
      }
    }
  }
  auto above = [&](int v) { return height(v) > 0; };

  // Vertices joined by the edges that stay on one side; the edges that cross, each with the
  // faces it bounds, sorted so that the two faces of an edge are neighbours.
  DisjointSets sides(n);
  struct Crossing {
    int a, b, face;  // a < b
    bool operator<(const Crossing& o) const {
      return std::array<int, 3>{a, b, face} < std::array<int, 3>{o.a, o.b, o.face};
    }
  };
  std::vector<Crossing> crossings;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      if (above(a) == above(b)) {
        sides.Unite(a, b);
      } else {
        crossings.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f)});
      }
    }
  }
  CutTopology out;
  if (crossings.empty()) {
    out.pieces = 1;
    out.genus = genus;
    return out;
  }
  std::sort(crossings.begin(), crossings.end());
  // Edge ids, and the loops: a crossed face's two crossing edges are consecutive on a loop.
  std::vector<int> edge_of(crossings.size());
  std::vector<std::array<int, 2>> edges;  // (a, b) of each crossing edge
  for (size_t i = 0; i < crossings.size(); ++i) {
    if (i == 0 || crossings[i].a != crossings[i - 1].a || crossings[i].b != crossings[i - 1].b) {
      edges.push_back({crossings[i].a, crossings[i].b});
    }
    edge_of[i] = static_cast<int>(edges.size()) - 1;
  }
  DisjointSets loops(static_cast<int>(edges.size()));
  std::map<int, std::vector<int>> edges_of_face;
  for (size_t i = 0; i < crossings.size(); ++i) {
    edges_of_face[crossings[i].face].push_back(edge_of[i]);
  }
  // The section in the plane's coordinates (the normal's largest coordinate dropped), as one
  // segment per crossed face.
  int drop = 0;
  plane.normal.cwiseAbs().maxCoeff(&drop);
  const int u = (drop + 1) % 3, w = (drop + 2) % 3;
  std::vector<Eigen::Vector2d> point(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    const int a = edges[e][0], b = edges[e][1];
    const double t = height(a) / (height(a) - height(b));
    const Eigen::Vector3d p =
        mesh.vertices.row(a) + t * (mesh.vertices.row(b) - mesh.vertices.row(a));
    point[e] = {p(u), p(w)};
  }
  struct Segment {
    int e0, e1;
  };
  std::vector<Segment> segments;
  for (const auto& [face, ids] : edges_of_face) {
    if (ids.size() != 2) continue;  // not a closed surface there: no loop through it
    loops.Unite(ids[0], ids[1]);
    segments.push_back({ids[0], ids[1]});
  }
  std::vector<int> loop_ids;  // loop roots, ascending
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    if (loops.Find(e) == e) loop_ids.push_back(e);
  }
  const int count = static_cast<int>(loop_ids.size());
  std::vector<int> index_of(edges.size());
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    index_of[static_cast<size_t>(e)] = static_cast<int>(
        std::lower_bound(loop_ids.begin(), loop_ids.end(), loops.Find(e)) - loop_ids.begin());
  }
  // contains[i][j]: loop j lies inside loop i (a ray from a point of j crosses i an odd number of
  // times).
  std::vector<std::vector<char>> contains(static_cast<size_t>(count),
                                          std::vector<char>(static_cast<size_t>(count), 0));
  for (int j = 0; j < count; ++j) {
    const Eigen::Vector2d& q = point[static_cast<size_t>(loop_ids[static_cast<size_t>(j)])];
    for (const Segment& s : segments) {
      const int i = index_of[static_cast<size_t>(s.e0)];
      if (i == j) continue;
      const Eigen::Vector2d& p0 = point[static_cast<size_t>(s.e0)];
      const Eigen::Vector2d& p1 = point[static_cast<size_t>(s.e1)];
      if ((p0.y() > q.y()) == (p1.y() > q.y())) continue;
      const double x = p0.x() + (q.y() - p0.y()) / (p1.y() - p0.y()) * (p1.x() - p0.x());
      if (x > q.x()) contains[static_cast<size_t>(i)][static_cast<size_t>(j)] ^= 1;
    }
  }
  // A loop's depth is the number of loops around it; a hole belongs to the region of the
  // deepest loop around it.
  std::vector<int> depth(static_cast<size_t>(count), 0), region(static_cast<size_t>(count));
  for (int j = 0; j < count; ++j) {
    for (int i = 0; i < count; ++i) depth[static_cast<size_t>(j)] += contains[i][j];
  }
  int regions = 0, holes = 0;
  for (int j = 0; j < count; ++j) {
    region[static_cast<size_t>(j)] = j;
    if (depth[static_cast<size_t>(j)] % 2 == 0) {
      ++regions;
      continue;
    }
    ++holes;
    int around = -1;
    for (int i = 0; i < count; ++i) {
      if (contains[i][j] &&
          (around < 0 || depth[static_cast<size_t>(i)] > depth[static_cast<size_t>(around)])) {
        around = i;
      }
    }
    if (around >= 0) region[static_cast<size_t>(j)] = around;
  }
  // Each region's cap joins, on each side, the components its loops' edges end in.
  std::vector<std::array<int, 2>> end_of_region(static_cast<size_t>(count), {-1, -1});
  for (size_t e = 0; e < edges.size(); ++e) {
    const int r = region[static_cast<size_t>(index_of[e])];
    for (const int v : edges[e]) {
      int& end = end_of_region[static_cast<size_t>(r)][above(v) ? 1 : 0];
      if (end < 0) {
        end = v;
      } else {
        sides.Unite(end, v);
      }
    }
  }
  std::vector<char> used(static_cast<size_t>(n), 0);
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) used[static_cast<size_t>(mesh.triangles(f, k))] = 1;
  }
  for (int v = 0; v < n; ++v) out.pieces += used[static_cast<size_t>(v)] && sides.Find(v) == v;
  out.genus = out.pieces - (1 - genus) - regions + holes;
  return out;
}

}  // namespace acdplan::acd::internal
