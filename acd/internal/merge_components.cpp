#include "acd/internal/merge_components.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/internal/exact_plane_split.h"
#include "acd/internal/face_intersections.h"
#include "acd/internal/neighbour_sets.h"
#include "acd/internal/solid_openings.h"
#include "acd/internal/subtree.h"
#include "acd/internal/winding_union.h"
#include "acd/mesh_measures.h"

namespace acdplan::acd::internal {
namespace {

using Triangle = std::array<int, 3>;

Triangle LowestFirst(const Triangle& t) {
  const int k = t[1] < t[0] ? (t[2] < t[1] ? 2 : 1) : (t[2] < t[0] ? 2 : 0);
  return {t[static_cast<size_t>(k)], t[static_cast<size_t>((k + 1) % 3)],
          t[static_cast<size_t>((k + 2) % 3)]};
}

void AppendVertices(const TriangleMesh& mesh, std::vector<Eigen::Vector3d>* points) {
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    points->emplace_back(mesh.vertices.row(i));
}

std::vector<Triangle> Triangles(const TriangleMesh& mesh) {
  std::vector<Triangle> out;
  out.reserve(static_cast<size_t>(mesh.triangles.rows()));
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    out.push_back({mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)});
  }
  return out;
}

// The closed pieces `a` and `b` as one triangle soup: vertices welded by exact position (the
// pieces share their rounded cut points), and without each triangle of `a` that `b` carries
// reversed, nor that copy in `b` (neither bounds their union, and in the winding number the
// two cancel). Pieces cut apart by one plane meet only along such faces until a later cut
// splits the section on one side; then what is left is their union's closed boundary.
struct GluedSoup {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Triangle> triangles;
  int glued = 0;  // the faces of `a` taken out with their copy in `b`

  // The soup as a mesh over the vertices its triangles use.
  TriangleMesh Mesh() const {
    std::vector<int> used(vertices.size(), -1);
    std::vector<Eigen::Vector3d> out_vertices;
    std::vector<Eigen::Vector3i> out_triangles;
    for (const Triangle& t : triangles) {
      Eigen::Vector3i u;
      for (int k = 0; k < 3; ++k) {
        int& v = used[static_cast<size_t>(t[static_cast<size_t>(k)])];
        if (v < 0) {
          v = static_cast<int>(out_vertices.size());
          out_vertices.push_back(vertices[static_cast<size_t>(t[static_cast<size_t>(k)])]);
        }
        u(k) = v;
      }
      out_triangles.push_back(u);
    }
    return MakeTriangleMesh(out_vertices, out_triangles);
  }
};

GluedSoup Glue(const TriangleMesh& a, const TriangleMesh& b) {
  GluedSoup out;
  std::map<std::array<double, 3>, int> index;
  auto welded = [&](const TriangleMesh& mesh) {
    std::vector<Triangle> triangles = Triangles(mesh);
    std::vector<int> id(static_cast<size_t>(mesh.vertices.rows()));
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      const auto [it, inserted] = index.emplace(
          std::array<double, 3>{mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)},
          static_cast<int>(out.vertices.size()));
      if (inserted) out.vertices.emplace_back(mesh.vertices.row(v));
      id[static_cast<size_t>(v)] = it->second;
    }
    for (Triangle& t : triangles) {
      t = LowestFirst({id[static_cast<size_t>(t[0])], id[static_cast<size_t>(t[1])],
                       id[static_cast<size_t>(t[2])]});
    }
    return triangles;
  };
  const std::vector<Triangle> ta = welded(a), tb = welded(b);
  std::map<Triangle, std::vector<size_t>> in_b;
  for (size_t i = 0; i < tb.size(); ++i) in_b[tb[i]].push_back(i);
  std::vector<char> b_gone(tb.size(), 0);
  for (const Triangle& t : ta) {
    const auto it = in_b.find(LowestFirst({t[0], t[2], t[1]}));
    if (it != in_b.end() && !it->second.empty()) {
      b_gone[it->second.back()] = 1;
      it->second.pop_back();
      ++out.glued;
    } else {
      out.triangles.push_back(t);
    }
  }
  for (size_t i = 0; i < tb.size(); ++i) {
    if (!b_gone[i]) out.triangles.push_back(tb[i]);
  }
  return out;
}

// A piece the solid ACD may output: one closed shell of genus 0 that is a valid solid in doubles.
bool IsValidPiece(const TriangleMesh& mesh) {
  const ExactPiece piece = ToExact(mesh);
  const ShellTopology topology = Topology(piece.triangles);
  return topology.closed && topology.shells == 1 && topology.genus == 0 &&
         RoundsToValidSolid(piece);
}

// The union of the adjacent closed pieces `a` and `b` as a valid piece, or nullopt.
std::optional<TriangleMesh> Unite(const TriangleMesh& a, const TriangleMesh& b) {
  const GluedSoup soup = Glue(a, b);
  const TriangleMesh mesh = soup.Mesh();
  if (soup.glued > 0) {
    const ExactPiece piece = ToExact(mesh);
    const ShellTopology topology = Topology(piece.triangles);
    if (topology.closed && RoundsToValidSolid(piece)) {
      // A valid closed surface whose winding number is the pieces' summed (their interiors
      // are disjoint) bounds their union: it is the piece, or the union is none (a handle where
      // they meet twice, or two shells).
      if (topology.shells == 1 && topology.genus == 0) return mesh;
      return std::nullopt;
    }
  }
  // Welded, faces that only touch along the edge or vertex they share are no crossing pair:
  // on mite at tau_rel 0.05, 100x fewer pairs to intersect exactly than the two meshes apart.
  std::vector<int> faces(static_cast<size_t>(mesh.triangles.rows()));
  std::iota(faces.begin(), faces.end(), 0);
  std::optional<WindingUnion> united = UniteByWinding(mesh, faces, IntersectingFacePairs(mesh));
  // A union that touches itself in a point, or leaves a speck, is no piece (UniteByWinding would
  // move or drop geometry to mend it).
  if (united && united->pinches == 0 && united->specks == 0 && IsValidPiece(united->mesh)) {
    return std::move(united->mesh);
  }
  return std::nullopt;
}

}  // namespace

Component3d SolidComponent(TriangleMesh mesh, const SolidConcavity& concavity, int source) {
  Component3d c;
  c.mesh = std::move(mesh);
  c.hull = concavity.hull;
  if (c.hull.triangles.rows() == 0) {
    std::vector<Eigen::Vector3d> points;
    AppendVertices(c.mesh, &points);
    c.hull = ConvexHull3(points, 0.0);
  }
  c.centroid = MeshCentroid(c.mesh, true);
  c.volume = MeshVolume(c.mesh);
  c.hull_volume = MeshVolume(c.hull);
  c.concavity = concavity.value;
  c.source = source;
  return c;
}

int MergeComponents(double tau, double max_growth, Decomposition3d* decomposition) {
  if (!(max_growth >= 0)) return 0;
  Decomposition3d& d = *decomposition;
  const int count = static_cast<int>(d.components.size());
  std::vector<std::set<int>> neighbours(static_cast<size_t>(count));
  for (const Opening3d& o : d.openings) {
    neighbours[static_cast<size_t>(o.component_a)].insert(o.component_b);
    neighbours[static_cast<size_t>(o.component_b)].insert(o.component_a);
  }
  // The pairs that pass the cheap tests, by growth (ties: the lower pair first). A pair is
  // united and measured only when it comes first: most pairs lose a piece to an earlier merge
  // before then, and the order is the same as with every pair united up front (a pair's
  // outcome depends on its two pieces alone).
  std::set<std::tuple<double, int, int>> candidates;
  auto consider = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    const Component3d& x = d.components[static_cast<size_t>(a)];
    const Component3d& y = d.components[static_cast<size_t>(b)];
    const double before = x.hull_volume + y.hull_volume;
    if (x.source != y.source || !(before > 0)) return;
    // The union's hull from the two hulls' vertices, which are their pieces' extreme points
    // (SolidComponent): the same hull, from far fewer points.
    std::vector<Eigen::Vector3d> corners;
    AppendVertices(x.hull, &corners);
    AppendVertices(y.hull, &corners);
    const TriangleMesh hull = ConvexHull3(corners, 0.0);
    std::vector<Eigen::Vector3d> points;
    AppendVertices(x.mesh, &points);
    AppendVertices(y.mesh, &points);
    const double growth = (MeshVolume(hull) - before) / before;
    if (!(growth <= max_growth)) return;
    // Every vertex of either piece is on the union's boundary (a cut face's corners lie on
    // the faces around it), and the concavity measures a boundary point at no less than its
    // depth below the nearest hull plane: a vertex deeper than tau rules the pair out.
    const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = HullPlanes(hull);
    for (const Eigen::Vector3d& p : points) {
      if ((planes.col(3) - planes.leftCols<3>() * p).minCoeff() > tau) return;
    }
    candidates.emplace(growth, a, b);
  };
  for (int a = 0; a < count; ++a) {
    for (int b : neighbours[static_cast<size_t>(a)]) {
      if (b > a) consider(a, b);
    }
  }
  int merges = 0;
  while (!candidates.empty()) {
    const auto [growth, a, b] = *candidates.begin();
    candidates.erase(candidates.begin());
    Component3d& kept = d.components[static_cast<size_t>(a)];
    std::optional<TriangleMesh> united =
        Unite(kept.mesh, d.components[static_cast<size_t>(b)].mesh);
    if (!united) continue;
    SolidConcavity concavity = MeasureSolidConcavity(*united, tau);
    if (!(concavity.value <= tau)) continue;
    kept = SolidComponent(std::move(*united), concavity, kept.source);
    d.components[static_cast<size_t>(b)] = Component3d{};
    for (auto it = candidates.begin(); it != candidates.end();) {
      const int p = std::get<1>(*it), q = std::get<2>(*it);
      it = (p == a || p == b || q == a || q == b) ? candidates.erase(it) : std::next(it);
    }
    ContractInto(a, b, &neighbours);
    for (HierarchyNode3d& node : d.tree) {
      if (node.component == b) node.component = a;
    }
    for (int c : neighbours[static_cast<size_t>(a)]) consider(a, c);
    ++merges;
  }
  if (merges == 0) return 0;
  // Renumber by first leaf in depth-first order, as the leaves were numbered.
  std::vector<int> id(static_cast<size_t>(count), -1);
  std::vector<Component3d> components;
  for (const int root : d.roots) {
    for (const int x : SubtreeDepthFirst(d.tree, root)) {
      HierarchyNode3d& node = d.tree[static_cast<size_t>(x)];
      if (node.component < 0) continue;
      int& to = id[static_cast<size_t>(node.component)];
      if (to < 0) {
        to = static_cast<int>(components.size());
        components.push_back(std::move(d.components[static_cast<size_t>(node.component)]));
      }
      node.component = to;
    }
  }
  d.components = std::move(components);
  ComputeOpenings(&d);
  return merges;
}

}  // namespace acdplan::acd::internal
