#include "acd/internal/surface_acd.h"

// Surface ACD (dissertation Sec. V.B, Table 5's "surface" columns): Algorithm 1 on sets of input
// faces. A patch is measured, and while its concavity exceeds tau it is split through its most
// concave point; the pieces are the edge-connected parts of each side. Patches stay unions of
// input faces: no geometry is constructed, so a patch needs no exact constructions and the
// partition of the input faces is exact by construction.
//
// Concavity of a patch (Sec. V.B.1): the largest distance of a patch point (its vertices and face
// centroids; the distance is concave over a face, so a face can hide depth its corners miss) to
// the boundary of the patch's convex hull. Inside a convex polytope that distance is the minimum
// over the hull's facet planes of the plane distance. It is a lower bound of Lien's bridge
// distance (a pocket point is measured against the nearest facet, not only its bridge), which
// makes the resolving step, not the measure, decide how pockets are separated. The open-surface
// rule of Sec. V.B.1 (a hull vertex whose surface normal opposes its hull normal is "concave" and
// the bridge edges ending there are projected to the opening) only changes which hull edges a
// bridge-projection measure projects; a distance-to-hull measure does not project, so an open
// surface, a surface whose inside faces the hull, and a closed surface are measured alike. A flat
// patch has a flat hull (ConvexHull3 with thickness 0) and concavity 0.
//
// Resolve (Sec. V.B.3, "surface ACD: cut along kappa's edges"): the cut runs along patch edges,
// chosen as the boundary between the faces whose centroids lie on either side of a plane through
// the witness. Candidate planes contain the witness and are scored by the concavity of the two
// sides (measured on a deterministic subsample; the union of a side's pieces is a conservative
// stand-in for the pieces, since a point is deeper in a larger convex set); the one with the
// smallest larger side concavity wins. The candidates: planes containing the witness's hull
// normal (they cut down through a groove, Fig. 43's "cut along the valley"), the plane parallel
// to the nearest hull facet, the coordinate planes and the patch's principal planes.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/internal/neighbour_sets.h"
#include "acd/mesh_measures.h"

namespace acdplan::acd::internal {
namespace {

// Points a candidate's side is scored on: a deterministic stride subsample of its faces.
constexpr int kScoreFaces = 600;
// Candidate directions in the plane perpendicular to the witness's hull normal.
constexpr int kFanDirections = 8;

// A part's faces with what the measure and the cuts need, computed once.
class SurfacePart {
 public:
  explicit SurfacePart(const TriangleMesh& mesh) : mesh_(mesh) {
    const Eigen::Index n = mesh.triangles.rows();
    centroids_.resize(static_cast<size_t>(n));
    for (Eigen::Index f = 0; f < n; ++f) {
      centroids_[static_cast<size_t>(f)] =
          (Vertex(mesh.triangles(f, 0)) + Vertex(mesh.triangles(f, 1)) +
           Vertex(mesh.triangles(f, 2))) /
          3.0;
    }
    // Undirected edges and their faces, sorted by (edge, face): the adjacency of faces across
    // edges (a non-manifold edge joins all its faces).
    edges_.reserve(static_cast<size_t>(3 * n));
    for (Eigen::Index f = 0; f < n; ++f) {
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
        edges_.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f)});
      }
    }
    std::sort(edges_.begin(), edges_.end());
    neighbours_.assign(static_cast<size_t>(n), {});
    for (size_t i = 0; i < edges_.size();) {
      size_t j = i;
      while (j < edges_.size() && edges_[j].a == edges_[i].a && edges_[j].b == edges_[i].b) ++j;
      for (size_t p = i; p < j; ++p) {
        for (size_t q = i; q < j; ++q) {
          if (p != q && edges_[p].face != edges_[q].face) {
            neighbours_[static_cast<size_t>(edges_[p].face)].push_back(edges_[q].face);
          }
        }
      }
      i = j;
    }
    for (auto& list : neighbours_) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
  }

  Eigen::Vector3d Vertex(int v) const { return mesh_.vertices.row(v).transpose(); }
  const Eigen::Vector3d& Centroid(int f) const { return centroids_[static_cast<size_t>(f)]; }
  int Corner(int f, int k) const { return mesh_.triangles(f, k); }
  const std::vector<int>& Neighbours(int f) const { return neighbours_[static_cast<size_t>(f)]; }
  const TriangleMesh& mesh() const { return mesh_; }

  struct EdgeFace {
    int a, b, face;
    bool operator<(const EdgeFace& o) const {
      return std::tie(a, b, face) < std::tie(o.a, o.b, o.face);
    }
  };
  const std::vector<EdgeFace>& edges() const { return edges_; }

 private:
  const TriangleMesh& mesh_;
  std::vector<Eigen::Vector3d> centroids_;
  std::vector<EdgeFace> edges_;
  std::vector<std::vector<int>> neighbours_;
};

// The distinct vertices of `faces` (ascending).
std::vector<int> PatchVertices(const SurfacePart& part, const std::vector<int>& faces) {
  std::vector<int> vertices;
  vertices.reserve(3 * faces.size());
  for (int f : faces) {
    for (int k = 0; k < 3; ++k) vertices.push_back(part.Corner(f, k));
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

struct Measure {
  double concavity = 0.0;
  Eigen::Vector3d witness = Eigen::Vector3d::Zero();
  Eigen::Vector3d hull_normal = Eigen::Vector3d::UnitZ();  ///< Of the facet nearest the witness.
  double hull_volume = 0.0;
};

// Largest distance of `points` (the first `vertex_count` of them vertices, the rest samples
// inside faces) to the boundary of their convex hull, and where it is reached.
Measure MeasurePoints(const std::vector<Eigen::Vector3d>& points, size_t vertex_count) {
  Measure out;
  if (vertex_count == 0) return out;
  const std::vector<Eigen::Vector3d> hull_points(points.begin(),
                                                 points.begin() + static_cast<long>(vertex_count));
  const TriangleMesh hull = ConvexHull3(hull_points, 0.0);
  out.hull_volume = MeshVolume(hull);
  const Eigen::AlignedBox3d box = BoundingBox(hull);
  const double size = box.diagonal().norm();
  // Flat (or collinear) patch: its hull bounds no volume, every point lies on it.
  if (!(size > 0) || !(out.hull_volume > 1e-12 * size * size * size)) return out;
  const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = HullPlanes(hull);
  // max over points of min over planes; a point stops as soon as it cannot beat the best.
  double best = 0.0;
  Eigen::Index best_plane = -1;
  for (const Eigen::Vector3d& p : points) {
    double depth = std::numeric_limits<double>::infinity();
    Eigen::Index nearest = -1;
    for (Eigen::Index r = 0; r < planes.rows(); ++r) {
      const double d = planes(r, 3) - planes.row(r).head<3>().dot(p);
      if (d < depth) {
        depth = d;
        nearest = r;
        if (depth <= best) break;
      }
    }
    if (depth > best) {
      best = depth;
      best_plane = nearest;
      out.witness = p;
    }
  }
  out.concavity = best;
  if (best_plane >= 0) out.hull_normal = planes.row(best_plane).head<3>().transpose();
  return out;
}

// Concavity of the patch `faces` over all its vertices and face centroids.
Measure MeasurePatch(const SurfacePart& part, const std::vector<int>& faces) {
  const std::vector<int> vertices = PatchVertices(part, faces);
  std::vector<Eigen::Vector3d> points;
  points.reserve(vertices.size() + faces.size());
  for (int v : vertices) points.push_back(part.Vertex(v));
  for (int f : faces) points.push_back(part.Centroid(f));
  return MeasurePoints(points, vertices.size());
}

// Cheaper estimate for scoring a side: the same measure on every stride-th face.
double EstimateConcavity(const SurfacePart& part, const std::vector<int>& faces, double* hull) {
  const size_t stride = std::max<size_t>(1, (faces.size() + kScoreFaces - 1) / kScoreFaces);
  std::vector<int> sample;
  sample.reserve(faces.size() / stride + 1);
  for (size_t i = 0; i < faces.size(); i += stride) sample.push_back(faces[i]);
  const Measure m = MeasurePatch(part, sample);
  *hull = m.hull_volume;
  return m.concavity;
}

// The edge-connected pieces of `faces` (each ascending; pieces ordered by their first face).
std::vector<std::vector<int>> ConnectedPieces(const SurfacePart& part,
                                              const std::vector<int>& faces) {
  std::map<int, int> label;  // face -> piece, -1 unvisited
  for (int f : faces) label[f] = -1;
  std::vector<std::vector<int>> pieces;
  for (int seed : faces) {
    if (label[seed] >= 0) continue;
    const int id = static_cast<int>(pieces.size());
    pieces.emplace_back();
    std::vector<int> stack = {seed};
    label[seed] = id;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      pieces.back().push_back(f);
      for (int g : part.Neighbours(f)) {
        const auto it = label.find(g);
        if (it == label.end() || it->second >= 0) continue;
        it->second = id;
        stack.push_back(g);
      }
    }
    std::sort(pieces.back().begin(), pieces.back().end());
  }
  return pieces;
}

double FaceArea(const SurfacePart& part, int f) {
  const Eigen::Vector3d a = part.Vertex(part.Corner(f, 0));
  return 0.5 *
         (part.Vertex(part.Corner(f, 1)) - a).cross(part.Vertex(part.Corner(f, 2)) - a).norm();
}

// A plane through a wavy surface leaves, besides the main piece of each side, slivers where
// the surface crosses the plane back and forth (faces are assigned by their centroids). Each
// piece smaller than kFragment of the patch's area, other than the largest of its side, joins the
// piece it shares most edges with (smallest first; ties to the lower index). The largest piece
// of each side never joins another, so at least two pieces remain and each is smaller than the
// patch: the recursion still progresses.
constexpr double kFragment = 0.05;
std::vector<std::vector<int>> AbsorbFragments(const SurfacePart& part,
                                              std::vector<std::vector<int>> pieces,
                                              const std::vector<int>& piece_side) {
  const int n = static_cast<int>(pieces.size());
  if (n <= 2) return pieces;
  std::vector<double> area(static_cast<size_t>(n), 0.0);
  std::map<int, int> owner;  // face -> piece
  double total = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int f : pieces[static_cast<size_t>(i)]) {
      area[static_cast<size_t>(i)] += FaceArea(part, f);
      owner[f] = i;
    }
    total += area[static_cast<size_t>(i)];
  }
  std::array<int, 2> main = {-1, -1};
  for (int i = 0; i < n; ++i) {
    int& m = main[static_cast<size_t>(piece_side[static_cast<size_t>(i)])];
    if (m < 0 || area[static_cast<size_t>(i)] > area[static_cast<size_t>(m)]) m = i;
  }
  std::vector<int> root(static_cast<size_t>(n));
  std::iota(root.begin(), root.end(), 0);
  auto find = [&root](int i) {
    while (root[static_cast<size_t>(i)] != i) i = root[static_cast<size_t>(i)];
    return i;
  };
  std::vector<std::pair<double, int>> order;
  for (int i = 0; i < n; ++i) {
    if (i != main[0] && i != main[1] && area[static_cast<size_t>(i)] < kFragment * total) {
      order.emplace_back(area[static_cast<size_t>(i)], i);
    }
  }
  std::sort(order.begin(), order.end());
  for (const auto& [a, i] : order) {
    std::map<int, int> shared;  // neighbouring piece (root) -> shared edges
    for (int f : pieces[static_cast<size_t>(i)]) {
      for (int g : part.Neighbours(f)) {
        const auto it = owner.find(g);
        if (it == owner.end()) continue;
        const int r = find(it->second);
        if (r != find(i)) ++shared[r];
      }
    }
    int best = -1;
    for (const auto& [r, count] : shared) {
      if (best < 0 || count > shared[best]) best = r;
    }
    if (best >= 0) root[static_cast<size_t>(find(i))] = best;
  }
  std::map<int, std::vector<int>> merged;  // root -> faces
  for (int i = 0; i < n; ++i) {
    auto& faces = merged[find(i)];
    faces.insert(faces.end(), pieces[static_cast<size_t>(i)].begin(),
                 pieces[static_cast<size_t>(i)].end());
  }
  std::vector<std::vector<int>> out;
  for (auto& [r, faces] : merged) {
    std::sort(faces.begin(), faces.end());
    out.push_back(std::move(faces));
  }
  return out;
}

Eigen::Vector3d AnyPerpendicular(const Eigen::Vector3d& n) {
  const Eigen::Vector3d axis = std::abs(n.x()) < 0.6   ? Eigen::Vector3d::UnitX()
                               : std::abs(n.y()) < 0.6 ? Eigen::Vector3d::UnitY()
                                                       : Eigen::Vector3d::UnitZ();
  return n.cross(axis).normalized();
}

// The principal axes of the faces' centroids (the eigenvectors of their covariance), by
// increasing variance: column 2 is the direction the faces spread along most.
Eigen::Matrix3d PrincipalAxes(const SurfacePart& part, const std::vector<int>& faces) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int f : faces) mean += part.Centroid(f);
  mean /= static_cast<double>(faces.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int f : faces) cov += (part.Centroid(f) - mean) * (part.Centroid(f) - mean).transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors();
}

// Unit normals of the candidate planes through the witness (duplicates removed).
std::vector<Eigen::Vector3d> CandidateNormals(const SurfacePart& part,
                                              const std::vector<int>& faces, const Measure& m) {
  std::vector<Eigen::Vector3d> normals;
  const Eigen::Vector3d h = m.hull_normal.normalized();
  const Eigen::Vector3d u = AnyPerpendicular(h), v = h.cross(u);
  for (int k = 0; k < kFanDirections; ++k) {
    const double angle = M_PI * k / kFanDirections;
    normals.push_back(std::cos(angle) * u + std::sin(angle) * v);
  }
  normals.push_back(h);
  normals.push_back(Eigen::Vector3d::UnitX());
  normals.push_back(Eigen::Vector3d::UnitY());
  normals.push_back(Eigen::Vector3d::UnitZ());
  // Principal planes of the face centroids.
  const Eigen::Matrix3d axes = PrincipalAxes(part, faces);
  for (int axis = 2; axis >= 0; --axis) normals.push_back(axes.col(axis));
  std::vector<Eigen::Vector3d> unique;
  for (const Eigen::Vector3d& n : normals) {
    if (!(n.norm() > 0.5)) continue;
    bool duplicate = false;
    for (const Eigen::Vector3d& q : unique) duplicate |= std::abs(q.dot(n)) > 1.0 - 1e-9;
    if (!duplicate) unique.push_back(n.normalized());
  }
  return unique;
}

struct Split {
  Plane3d plane;
  std::array<std::vector<int>, 2> sides;
};

// Faces whose centroid lies strictly above the plane go to side 1, the others to side 0.
std::array<std::vector<int>, 2> SplitByPlane(const SurfacePart& part, const std::vector<int>& faces,
                                             const Plane3d& plane) {
  std::array<std::vector<int>, 2> sides;
  for (int f : faces) {
    sides[plane.normal.dot(part.Centroid(f)) > plane.offset ? 1 : 0].push_back(f);
  }
  return sides;
}

// Resolve (Sec. V.B.3): the best candidate plane through the witness; when no candidate leaves
// faces on both sides, the median split along the principal axis, which always does.
Split Resolve(const SurfacePart& part, const std::vector<int>& faces, const Measure& m) {
  Split best;
  double best_score = std::numeric_limits<double>::infinity(), best_hull = best_score;
  for (const Eigen::Vector3d& n : CandidateNormals(part, faces, m)) {
    const Plane3d plane{n, n.dot(m.witness)};
    std::array<std::vector<int>, 2> sides = SplitByPlane(part, faces, plane);
    if (sides[0].empty() || sides[1].empty()) continue;
    double hull0 = 0.0, hull1 = 0.0;
    const double score = std::max(EstimateConcavity(part, sides[0], &hull0),
                                  EstimateConcavity(part, sides[1], &hull1));
    if (score < best_score || (score == best_score && hull0 + hull1 < best_hull)) {
      best_score = score;
      best_hull = hull0 + hull1;
      best.plane = plane;
      best.sides = std::move(sides);
    }
  }
  if (!best.sides[0].empty()) return best;
  // Median of the centroids' projections on the principal axis (ties by face index).
  const Eigen::Vector3d axis = PrincipalAxes(part, faces).col(2).normalized();
  std::vector<std::pair<double, int>> order;
  for (int f : faces) order.emplace_back(axis.dot(part.Centroid(f)), f);
  std::sort(order.begin(), order.end());
  const size_t half = order.size() / 2;
  for (size_t i = 0; i < order.size(); ++i) best.sides[i < half ? 0 : 1].push_back(order[i].second);
  for (auto& side : best.sides) std::sort(side.begin(), side.end());
  best.plane = {axis, 0.5 * (order[half - 1].first + order[half].first)};
  return best;
}

// ConvexHull3 of a flat point set is one-sided; the component's hull is closed (every edge
// paired, volume 0), so it gets both sides.
TriangleMesh ClosedHull(const std::vector<Eigen::Vector3d>& points) {
  TriangleMesh hull = ConvexHull3(points, 0.0);
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < hull.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) ++directed[{hull.triangles(f, k), hull.triangles(f, (k + 1) % 3)}];
  }
  bool closed = true;
  for (const auto& [edge, n] : directed) closed &= directed.count({edge.second, edge.first}) > 0;
  if (closed) return hull;
  const Eigen::Index n = hull.triangles.rows();
  hull.triangles.conservativeResize(2 * n, 3);
  for (Eigen::Index f = 0; f < n; ++f) {
    hull.triangles.row(n + f) << hull.triangles(f, 0), hull.triangles(f, 2), hull.triangles(f, 1);
  }
  return hull;
}

Component3d MakeComponent(const SurfacePart& part, const std::vector<int>& faces, double concavity,
                          int source) {
  std::map<int, int> index;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (int f : faces) {
    Eigen::Vector3i t;
    for (int k = 0; k < 3; ++k) {
      const int v = part.Corner(f, k);
      const auto [it, inserted] = index.emplace(v, static_cast<int>(vertices.size()));
      if (inserted) vertices.push_back(part.Vertex(v));
      t(k) = it->second;
    }
    triangles.push_back(t);
  }
  Component3d c;
  c.mesh = MakeTriangleMesh(vertices, triangles);
  c.hull = ClosedHull(vertices);
  c.centroid = MeshCentroid(c.mesh, false);
  c.volume = 0.0;
  c.hull_volume = MeshVolume(c.hull);
  c.concavity = concavity;
  c.source = source;
  return c;
}

// The polylines along which the leaves of one part meet: for every pair of components, the
// edges with faces in both, chained at vertices where exactly two of them meet. A closed loop
// repeats its first vertex at its end.
void AddOpenings(const SurfacePart& part, const std::vector<int>& face_component,
                 std::vector<Opening3d>* openings) {
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> shared;
  const auto& edges = part.edges();
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
    std::vector<int> comps;
    for (size_t p = i; p < j; ++p) comps.push_back(face_component[edges[p].face]);
    std::sort(comps.begin(), comps.end());
    comps.erase(std::unique(comps.begin(), comps.end()), comps.end());
    for (size_t p = 0; p < comps.size(); ++p) {
      for (size_t q = p + 1; q < comps.size(); ++q) {
        shared[{comps[p], comps[q]}].emplace_back(edges[i].a, edges[i].b);
      }
    }
    i = j;
  }
  for (const auto& [pair, list] : shared) {
    std::map<int, std::vector<int>> adjacent;  // vertex -> edge indices
    for (size_t e = 0; e < list.size(); ++e) {
      adjacent[list[e].first].push_back(static_cast<int>(e));
      adjacent[list[e].second].push_back(static_cast<int>(e));
    }
    std::vector<bool> used(list.size(), false);
    // Chains start at vertices that do not continue a chain (degree != 2), then loops.
    std::vector<int> starts;
    for (const auto& [v, incident] : adjacent) {
      if (incident.size() != 2) starts.push_back(v);
    }
    for (const auto& [v, incident] : adjacent) {
      if (incident.size() == 2) starts.push_back(v);
    }
    for (int start : starts) {
      for (int first : adjacent[start]) {
        if (used[static_cast<size_t>(first)]) continue;
        std::vector<int> chain = {start};
        int v = start, e = first;
        while (true) {
          used[static_cast<size_t>(e)] = true;
          const int w = list[static_cast<size_t>(e)].first == v
                            ? list[static_cast<size_t>(e)].second
                            : list[static_cast<size_t>(e)].first;
          chain.push_back(w);
          v = w;
          const std::vector<int>& next = adjacent[v];
          if (next.size() != 2) break;
          e = used[static_cast<size_t>(next[0])] ? next[1] : next[0];
          if (used[static_cast<size_t>(e)]) break;
        }
        Opening3d opening;
        for (int u : chain) opening.polygon.push_back(part.Vertex(u));
        opening.component_a = pair.first;
        opening.component_b = pair.second;
        openings->push_back(std::move(opening));
      }
    }
  }
}

// After Algorithm 1 on a part: adjacent patches whose union is within tau are merged, the pair
// whose union is least concave first, until no adjacent pair's union is within tau. A cut through
// the most concave point resolves it, but its sides are cut again where their own witnesses lie,
// so patches on either side of an early cut that together are nearly convex stay apart (bunny.obj
// at tau_rel 0.02: 146 patches, against the dissertation's Table 5's 97). Every patch, merged or
// not, is still measured by MeasurePatch, so the result stays tau-convex. The hierarchy keeps the
// surviving leaf of each merged pair (its node takes the union); the other leaf leaves the tree,
// and an internal node left with one child is replaced by that child. Components are renumbered
// in depth-first order of the leaves. O(M P) measures for M merges and P adjacent pairs per patch.
void MergePatches(const SurfacePart& part, int source, double tau, int base, int first_component,
                  std::vector<int>* face_component, Decomposition3d* out) {
  const int count = static_cast<int>(out->components.size()) - first_component;
  if (count < 2) return;
  std::vector<std::vector<int>> faces(static_cast<size_t>(count));
  for (size_t f = 0; f < face_component->size(); ++f) {
    faces[static_cast<size_t>((*face_component)[f] - first_component)].push_back(
        static_cast<int>(f));
  }
  std::vector<std::set<int>> neighbours(static_cast<size_t>(count));
  const auto& edges = part.edges();
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
    for (size_t p = i; p < j; ++p) {
      for (size_t q = i; q < j; ++q) {
        const int a = (*face_component)[static_cast<size_t>(edges[p].face)] - first_component;
        const int b = (*face_component)[static_cast<size_t>(edges[q].face)] - first_component;
        if (a != b) neighbours[static_cast<size_t>(a)].insert(b);
      }
    }
    i = j;
  }
  auto united = [&](int a, int b) {
    std::vector<int> u;
    std::merge(faces[static_cast<size_t>(a)].begin(), faces[static_cast<size_t>(a)].end(),
               faces[static_cast<size_t>(b)].begin(), faces[static_cast<size_t>(b)].end(),
               std::back_inserter(u));
    return u;
  };
  std::vector<int> version(static_cast<size_t>(count), 0);
  std::vector<char> alive(static_cast<size_t>(count), 1), merged(static_cast<size_t>(count), 0);
  std::vector<Measure> measure(static_cast<size_t>(count));
  // (union concavity, a, b, version of a, version of b), a < b: least concave first.
  std::set<std::tuple<double, int, int, int, int>> queue;
  auto consider = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    const double c = MeasurePatch(part, united(a, b)).concavity;
    if (c <= tau)
      queue.emplace(c, a, b, version[static_cast<size_t>(a)], version[static_cast<size_t>(b)]);
  };
  for (int a = 0; a < count; ++a) {
    for (int b : neighbours[static_cast<size_t>(a)]) {
      if (a < b) consider(a, b);
    }
  }
  while (!queue.empty()) {
    const auto [c, a, b, va, vb] = *queue.begin();
    queue.erase(queue.begin());
    if (!alive[static_cast<size_t>(a)] || !alive[static_cast<size_t>(b)] ||
        va != version[static_cast<size_t>(a)] || vb != version[static_cast<size_t>(b)]) {
      continue;
    }
    faces[static_cast<size_t>(a)] = united(a, b);
    faces[static_cast<size_t>(b)].clear();
    measure[static_cast<size_t>(a)] = MeasurePatch(part, faces[static_cast<size_t>(a)]);
    merged[static_cast<size_t>(a)] = 1;
    alive[static_cast<size_t>(b)] = 0;
    ++version[static_cast<size_t>(a)];
    ContractInto(a, b, &neighbours);
    for (int n : neighbours[static_cast<size_t>(a)]) consider(a, n);
  }
  // The hierarchy: drop the merged-away leaves and the internal nodes left with one child.
  const int end = static_cast<int>(out->tree.size());
  std::vector<char> node_alive(static_cast<size_t>(end - base), 1);
  auto node = [&](int n) -> HierarchyNode3d& { return out->tree[static_cast<size_t>(n)]; };
  for (int n = base; n < end; ++n) {
    if (!node(n).children.empty()) continue;
    const int local = node(n).component - first_component;
    if (alive[static_cast<size_t>(local)]) {
      if (merged[static_cast<size_t>(local)]) {
        node(n).concavity = measure[static_cast<size_t>(local)].concavity;
        node(n).witness = measure[static_cast<size_t>(local)].witness;
      }
      continue;
    }
    node_alive[static_cast<size_t>(n - base)] = 0;
    const int parent = node(n).parent;
    auto& siblings = node(parent).children;
    siblings.erase(std::find(siblings.begin(), siblings.end(), n));
    if (siblings.size() != 1) continue;
    const int only = siblings[0];  // the parent is replaced by its one remaining child
    node_alive[static_cast<size_t>(parent - base)] = 0;
    const int grand = node(parent).parent;
    node(only).parent = grand;
    if (grand >= 0) {
      std::replace(node(grand).children.begin(), node(grand).children.end(), parent, only);
    } else {
      out->roots.back() = only;
    }
  }
  std::vector<int> id(static_cast<size_t>(end - base), -1);
  std::vector<HierarchyNode3d> kept;
  for (int n = base; n < end; ++n) {
    if (!node_alive[static_cast<size_t>(n - base)]) continue;
    id[static_cast<size_t>(n - base)] = base + static_cast<int>(kept.size());
    kept.push_back(node(n));
  }
  auto renumber = [&](int n) { return n < base ? n : id[static_cast<size_t>(n - base)]; };
  for (HierarchyNode3d& k : kept) {
    if (k.parent >= 0) k.parent = renumber(k.parent);
    for (int& ch : k.children) ch = renumber(ch);
  }
  out->tree.resize(static_cast<size_t>(base));
  out->tree.insert(out->tree.end(), kept.begin(), kept.end());
  out->roots.back() = renumber(out->roots.back());
  // Depths and components in depth-first order of the leaves.
  std::vector<Component3d> old(std::make_move_iterator(out->components.begin() + first_component),
                               std::make_move_iterator(out->components.end()));
  out->components.resize(static_cast<size_t>(first_component));
  std::vector<int> stack = {out->roots.back()};
  node(out->roots.back()).depth = 0;
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    HierarchyNode3d& x = node(n);
    if (x.children.empty()) {
      const int local = x.component - first_component;
      const int component = static_cast<int>(out->components.size());
      for (int f : faces[static_cast<size_t>(local)]) {
        (*face_component)[static_cast<size_t>(f)] = component;
      }
      out->components.push_back(merged[static_cast<size_t>(local)]
                                    ? MakeComponent(part, faces[static_cast<size_t>(local)],
                                                    measure[static_cast<size_t>(local)].concavity,
                                                    source)
                                    : std::move(old[static_cast<size_t>(local)]));
      x.component = component;
      continue;
    }
    for (auto it = x.children.rbegin(); it != x.children.rend(); ++it) {
      node(*it).depth = x.depth + 1;
      stack.push_back(*it);
    }
  }
}

// Algorithm 1 on one part, appending its nodes, leaves and openings to `out`.
void DecomposePart(const TriangleMesh& mesh, int source, double tau, Decomposition3d* out) {
  const SurfacePart part(mesh);
  std::vector<int> all(static_cast<size_t>(mesh.triangles.rows()));
  std::iota(all.begin(), all.end(), 0);
  std::vector<std::vector<int>> faces_of;  // per tree node of this part (by tree index - base)
  const int base = static_cast<int>(out->tree.size());
  const int first_component = static_cast<int>(out->components.size());
  out->roots.push_back(base);
  out->tree.push_back({});
  faces_of.push_back(std::move(all));
  std::vector<int> face_component(static_cast<size_t>(mesh.triangles.rows()), -1);
  std::vector<int> stack = {base};
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    const std::vector<int> faces = std::move(faces_of[static_cast<size_t>(id - base)]);
    const Measure m = MeasurePatch(part, faces);
    out->tree[id].concavity = m.concavity;
    out->tree[id].witness = m.witness;
    if (m.concavity <= tau || faces.size() == 1) {
      const int component = static_cast<int>(out->components.size());
      out->tree[id].component = component;
      for (int f : faces) face_component[static_cast<size_t>(f)] = component;
      out->components.push_back(MakeComponent(part, faces, m.concavity, source));
      continue;
    }
    Split split = Resolve(part, faces, m);
    out->tree[id].cut = split.plane;
    std::vector<std::vector<int>> pieces;
    std::vector<int> piece_side;
    for (int side = 0; side < 2; ++side) {
      for (auto& piece : ConnectedPieces(part, split.sides[side])) {
        pieces.push_back(std::move(piece));
        piece_side.push_back(side);
      }
    }
    pieces = AbsorbFragments(part, std::move(pieces), piece_side);
    // Children in the order of their pieces; pushed reversed so the first is processed first
    // and the leaves come out in depth-first order.
    std::vector<int> children;
    for (auto& piece : pieces) {
      const int child = static_cast<int>(out->tree.size());
      HierarchyNode3d node;
      node.parent = id;
      node.depth = out->tree[id].depth + 1;
      out->tree.push_back(node);
      faces_of.push_back(std::move(piece));
      children.push_back(child);
    }
    out->tree[id].children = children;
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(*it);
  }
  MergePatches(part, source, tau, base, first_component, &face_component, out);
  AddOpenings(part, face_component, &out->openings);
}

}  // namespace

Decomposition3d DecomposeSurface(const PreparedMesh& prepared, double tau) {
  Decomposition3d out;
  out.tau = tau;
  for (int i = 0; i < static_cast<int>(prepared.parts.size()); ++i) {
    // In canonical numbering, so that ties are not settled by the file's (as in the solid ACD).
    DecomposePart(CanonicallyNumbered(prepared.parts[static_cast<size_t>(i)]), i, tau, &out);
  }
  out.stats.vertices = static_cast<int>(prepared.mesh.vertices.rows());
  out.stats.triangles = static_cast<int>(prepared.mesh.triangles.rows());
  out.stats.components = static_cast<int>(out.components.size());
  out.stats.surface = true;
  for (const Component3d& c : out.components) {
    out.stats.hull_volume += c.hull_volume;
    out.stats.max_concavity = std::max(out.stats.max_concavity, c.concavity);
  }
  return out;
}

}  // namespace acdplan::acd::internal
