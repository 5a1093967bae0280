#include "acd/internal/solid_concavity.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/internal/canonical_hull.h"
#include "acd/internal/in_plane_tolerance.h"
#include "acd/mesh_measures.h"

namespace acdplan::acd::internal {
namespace {

// Whether the points span an area (are not all on one line), to `tol` [units].
bool SpansArea(const std::vector<Eigen::Vector3d>& p, double tol) {
  if (p.size() < 3) return false;
  size_t b = 0;
  double far = -1;
  for (size_t i = 1; i < p.size(); ++i) {
    const double d = (p[i] - p[0]).squaredNorm();
    if (d > far) far = d, b = i;
  }
  const Eigen::Vector3d ab = p[b] - p[0];
  const double len = ab.norm();
  if (!(len > tol)) return false;
  for (const auto& q : p) {
    if (ab.cross(q - p[0]).norm() / len > tol) return true;
  }
  return false;
}

}  // namespace

SolidConcavity MeasureSolidConcavity(const TriangleMesh& mesh, double tau) {
  SolidConcavity out;
  const Eigen::Index n = mesh.vertices.rows();
  const Eigen::Index nf = mesh.triangles.rows();
  if (n < 4 || nf < 4) return out;
  std::vector<Eigen::Vector3d> points(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) points[static_cast<size_t>(i)] = mesh.vertices.row(i);
  CanonicalHull hull = MakeCanonicalHull(points);
  out.hull = std::move(hull.mesh);
  out.hull_volume = MeshVolume(out.hull);
  const double scale = BoundingBox(mesh).diagonal().norm();
  const double tol = kInPlaneTolerance * scale;  // the hull's planes are regrouped at this
  if (IsFlatHull(out.hull) || !(out.hull_volume > 0)) return out;
  const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes = hull.planes;
  const int m = static_cast<int>(planes.rows());
  // Fewer than four planes need not mean flat: MakeCanonicalHull drops a regrouped plane that a
  // hull vertex lies clearly outside of (fuzz_decompose3d: a solid 0.76 deep whose hull of 5
  // vertices kept 3 planes, measured 0 as flat). Flatness is the width test below; the planes
  // kept still bound every depth from above.
  auto depth = [&](const Eigen::Vector3d& p, int j) {
    return planes(j, 3) - planes.row(j).head<3>().dot(p);
  };
  // A plate within tol of one of its hull's planes is flat: no point of it is deeper than tol.
  // (Not a small hull volume: a needle's is as small, and its points can be far deeper.)
  for (int j = 0; j < m; ++j) {
    double width = 0;
    for (Eigen::Index i = 0; i < out.hull.vertices.rows() && width <= tol; ++i) {
      width = std::max(width, depth(out.hull.vertices.row(i).transpose(), j));
    }
    if (width <= tol) return out;
  }
  // The hull planes each vertex lies in.
  std::vector<std::vector<int>> on(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      if (depth(points[static_cast<size_t>(i)], j) <= tol) on[static_cast<size_t>(i)].push_back(j);
    }
  }
  // Hull facet area per plane, and the area of surface faces lying in it.
  std::vector<double> facet_area(static_cast<size_t>(m), 0.0), covered(static_cast<size_t>(m), 0.0);
  for (Eigen::Index f = 0; f < out.hull.triangles.rows(); ++f) {
    const Eigen::Vector3d a = out.hull.vertices.row(out.hull.triangles(f, 0));
    const Eigen::Vector3d b = out.hull.vertices.row(out.hull.triangles(f, 1));
    const Eigen::Vector3d c = out.hull.vertices.row(out.hull.triangles(f, 2));
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    if (!(cross.norm() > 0)) continue;
    const Eigen::Vector3d normal = cross.normalized();
    int best = 0;
    double best_score = -1e300;
    for (int j = 0; j < m; ++j) {
      const double s = planes.row(j).head<3>().dot(normal) - std::abs(depth((a + b + c) / 3, j));
      if (s > best_score) best_score = s, best = j;
    }
    facet_area[static_cast<size_t>(best)] += 0.5 * cross.norm();
  }
  std::vector<char> on_hull(static_cast<size_t>(nf), 0);
  for (Eigen::Index f = 0; f < nf; ++f) {
    const auto& a = on[static_cast<size_t>(mesh.triangles(f, 0))];
    const auto& b = on[static_cast<size_t>(mesh.triangles(f, 1))];
    const auto& c = on[static_cast<size_t>(mesh.triangles(f, 2))];
    for (int j : a) {
      if (std::find(b.begin(), b.end(), j) != b.end() &&
          std::find(c.begin(), c.end(), j) != c.end()) {
        on_hull[static_cast<size_t>(f)] = 1;
        const Eigen::Vector3d p0 = mesh.vertices.row(mesh.triangles(f, 0));
        const Eigen::Vector3d p1 = mesh.vertices.row(mesh.triangles(f, 1));
        const Eigen::Vector3d p2 = mesh.vertices.row(mesh.triangles(f, 2));
        covered[static_cast<size_t>(j)] += 0.5 * (p1 - p0).cross(p2 - p0).norm();
        break;
      }
    }
  }
  std::vector<char> bridge(static_cast<size_t>(m), 0);
  for (int j = 0; j < m; ++j) {
    const double area = facet_area[static_cast<size_t>(j)];
    bridge[static_cast<size_t>(j)] =
        covered[static_cast<size_t>(j)] < area - (1e-7 * area + tol * scale);
  }
  // Pockets: off-hull faces connected through shared edges.
  std::vector<int> parent(static_cast<size_t>(nf));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[static_cast<size_t>(x)] != x)
      x = parent[static_cast<size_t>(x)] =
          parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    return x;
  };
  std::map<std::pair<int, int>, int> edge_face;
  for (Eigen::Index f = 0; f < nf; ++f) {
    if (on_hull[static_cast<size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      if (a > b) std::swap(a, b);
      auto [it, inserted] = edge_face.emplace(std::make_pair(a, b), static_cast<int>(f));
      if (!inserted) {
        const int ra = find(static_cast<int>(f)), rb = find(it->second);
        if (ra != rb) parent[static_cast<size_t>(std::max(ra, rb))] = std::min(ra, rb);
      }
    }
  }
  std::map<int, std::vector<int>> pockets;  // root -> faces, in face order
  for (Eigen::Index f = 0; f < nf; ++f) {
    if (!on_hull[static_cast<size_t>(f)])
      pockets[find(static_cast<int>(f))].push_back(static_cast<int>(f));
  }
  const double spacing = tau > 0 ? tau : scale / 8;
  out.face_pocket.assign(static_cast<size_t>(nf), -1);
  out.vertex_concavity.assign(static_cast<size_t>(n), 0.0);
  // The deepest vertex is the witness unless a face sample is deeper by more than `tol`: a
  // notch's corner offers its walls as cut planes, a face sample only its face's, and on a
  // floor as deep as the notch (a slot under a flat bridge) rounding decides which is deeper
  // once the model is turned off the axes (measured: cube-notch turned at random, 3 components
  // became 12 to 17, slivers cut along its floor's plane).
  struct Deepest {
    double value = 0.0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    int vertex = -1, face = -1, pocket = -1;
  };
  Deepest deepest_vertex, deepest_sample;
  std::vector<const std::vector<int>*> pocket_faces;  // by pocket id
  int pocket_id = -1;
  for (const auto& [root, faces] : pockets) {
    ++pocket_id;
    for (int f : faces) out.face_pocket[static_cast<size_t>(f)] = pocket_id;
    // Border vertices and the bridge planes they span.
    std::map<int, std::vector<Eigen::Vector3d>> in_plane;
    std::vector<int> verts;
    for (int f : faces) {
      for (int k = 0; k < 3; ++k) verts.push_back(mesh.triangles(f, k));
    }
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    for (int v : verts) {
      for (int j : on[static_cast<size_t>(v)]) {
        if (bridge[static_cast<size_t>(j)]) in_plane[j].push_back(points[static_cast<size_t>(v)]);
      }
    }
    std::vector<int> bridge_planes;
    for (const auto& [j, pts] : in_plane) {
      if (SpansArea(pts, tol)) bridge_planes.push_back(j);
    }
    // Algorithm 6 (bridge clustering, epsilon = tau / 2): a bridge plane whose border
    // vertices all lie within epsilon of a patch's plane joins that patch, and its points are
    // measured from the patch's plane (Obs. B.1: off by less than epsilon). Planes holding
    // more border vertices seed patches first.
    if (tau > 0 && bridge_planes.size() > 1) {
      const double epsilon = tau / 2;
      std::stable_sort(bridge_planes.begin(), bridge_planes.end(),
                       [&](int a, int b) { return in_plane[a].size() > in_plane[b].size(); });
      std::vector<int> seeds;
      for (int j : bridge_planes) {
        bool absorbed = false;
        for (int seed : seeds) {
          bool near = true;
          for (const auto& p : in_plane[j]) near = near && std::abs(depth(p, seed)) <= epsilon;
          if (near) {
            absorbed = true;
            break;
          }
        }
        if (!absorbed) seeds.push_back(j);
      }
      std::sort(seeds.begin(), seeds.end());
      bridge_planes = std::move(seeds);
    }
    if (bridge_planes.empty()) {
      bridge_planes.resize(static_cast<size_t>(m));
      std::iota(bridge_planes.begin(), bridge_planes.end(), 0);
    }
    // A point is measured against the bridge planes its surface faces (Lien projects a
    // pocket point onto the bridge above it): a lid plane its wall meets at a right angle
    // is not above it. A point facing none of them is measured against them all.
    auto measure = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& normal) {
      double facing = 1e300, any = 1e300;
      for (int j : bridge_planes) {
        const double d = depth(p, j);
        any = std::min(any, d);
        if (planes.row(j).head<3>().dot(normal) > 1e-6) facing = std::min(facing, d);
      }
      return std::max(facing < 1e300 ? facing : any, 0.0);
    };
    pocket_faces.push_back(&faces);
    const int id = pocket_id;
    auto consider = [&](const Eigen::Vector3d& p, double d, int vertex, int face) {
      Deepest& best = vertex >= 0 ? deepest_vertex : deepest_sample;
      if (d > best.value) best = {d, p, vertex, face, id};
    };
    std::map<int, int> vertex_face;
    std::map<int, Eigen::Vector3d> vertex_normal;  // area-weighted, over the pocket's faces
    std::vector<Eigen::Vector3d> face_normal;
    for (int f : faces) {
      const Eigen::Vector3d& a = points[static_cast<size_t>(mesh.triangles(f, 0))];
      const Eigen::Vector3d& b = points[static_cast<size_t>(mesh.triangles(f, 1))];
      const Eigen::Vector3d& c = points[static_cast<size_t>(mesh.triangles(f, 2))];
      const Eigen::Vector3d n = (b - a).cross(c - a);
      face_normal.push_back(n.normalized());
      for (int k = 0; k < 3; ++k) {
        vertex_face.emplace(mesh.triangles(f, k), f);
        auto [it, inserted] = vertex_normal.emplace(mesh.triangles(f, k), n);
        if (!inserted) it->second += n;
      }
    }
    for (int v : verts) {
      const Eigen::Vector3d& p = points[static_cast<size_t>(v)];
      const double d = measure(p, vertex_normal[v]);
      double& stored = out.vertex_concavity[static_cast<size_t>(v)];
      stored = std::max(stored, d);
      consider(p, d, v, vertex_face[v]);
    }
    for (size_t fi = 0; fi < faces.size(); ++fi) {
      const int f = faces[fi];
      const Eigen::Vector3d& normal = face_normal[fi];
      const Eigen::Vector3d& a = points[static_cast<size_t>(mesh.triangles(f, 0))];
      const Eigen::Vector3d& b = points[static_cast<size_t>(mesh.triangles(f, 1))];
      const Eigen::Vector3d& c = points[static_cast<size_t>(mesh.triangles(f, 2))];
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      const int k = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 8);
      const Eigen::Vector3d centroid = (a + b + c) / 3;
      consider(centroid, measure(centroid, normal), -1, f);
      if (k == 1) continue;
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; i + j <= k; ++j) {
          if (i == k || j == k || i + j == 0) continue;  // the corners are vertices
          const Eigen::Vector3d p = a + (b - a) * (double(i) / k) + (c - a) * (double(j) / k);
          consider(p, measure(p, normal), -1, f);
        }
      }
    }
  }
  const Deepest& witness =
      deepest_vertex.vertex >= 0 && deepest_vertex.value >= deepest_sample.value - tol
          ? deepest_vertex
          : deepest_sample;
  out.value = std::max(deepest_vertex.value, deepest_sample.value);
  if (witness.pocket >= 0) {
    out.witness = witness.point;
    out.witness_vertex = witness.vertex;
    out.witness_face = witness.face;
    out.witness_pocket = witness.pocket;
    out.pocket_faces = *pocket_faces[static_cast<size_t>(witness.pocket)];
  }
  if (out.value <= tol) {
    out.value = 0.0;
    out.witness_vertex = -1;
    out.witness_face = -1;
    out.witness_pocket = -1;
    out.pocket_faces.clear();
  }
  return out;
}

}  // namespace acdplan::acd::internal
