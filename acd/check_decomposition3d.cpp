#include "acd/check_decomposition3d.h"

// What a clean result of CheckDecomposition3d() proves, per PreparedMesh part P and its
// components C_1..C_m (components of different parts are not compared: each part is decomposed
// on its own).
//
// Solid ACD:
//  1. Every C_i is closed and consistently oriented (every directed edge, vertices identified by
//     position, is matched by exactly one opposite edge), bounds a positive volume (outward) and
//     does not self-intersect (CGAL PMP, exact predicates): it is the boundary of a solid.
//  2. Interiors are disjoint and the components lie inside P, tested on deterministic samples:
//     points just inside each C_i (a seeded point on a face, moved a little along the inward
//     normal, kept only if Side_of_triangle_mesh puts it strictly inside C_i) must be strictly
//     inside no other C_j and not outside P; every vertex of C_i outside P must lie within the
//     distance tolerance of P's boundary.
//  3. Sum of Volume(C_i) equals Volume(P) to 1e-6 relative.
//  From 2 and 3 the components tile P up to what the samples can miss; 3 alone catches any gap
//  or overlap of measurable volume, 2 names where.
// Surface ACD: every face of P occurs in exactly one patch (faces matched by their three corner
// positions, orientation aside) and the patch areas sum to P's area (1e-9 relative): the patches
// partition P's faces exactly.
// Both: the stored hull contains its component (every vertex on the inner side of every hull
// plane, within the tolerance) and is closed; the stored volume, hull volume and centroid agree
// with MeshVolume / MeshCentroid; the concavity re-measure (below) is at most tau unless a
// max_hulls cap merged components; every opening lies in the boundaries of both of its
// components (solid: its vertices within the tolerance of both surfaces, its area and normal
// those of its polygon less its holes, each hole clockwise; surface: each of its segments an
// edge of both patches, no holes); the tree, the roots and the stats are consistent.
//
// Concavity re-measure: the largest distance of a component vertex or face centroid to the
// boundary of the convex hull of the component's vertices (recomputed, not the stored hull).
// Inside a convex polytope this distance is the minimum over facet planes. It is a lower bound of
// Lien's concavity (Sec. V.B.1, the largest bridge distance of a vertex): a point is no farther
// from the hull boundary than from its bridge's plane, and a face centroid no farther from that
// plane than the face's farthest vertex. It equals the surface ACD's own measure. A correct result
// never fails it; it catches gross errors (an unresolved pocket, a concavity stored lower than its
// lower bound), not every component above tau.
//
// Tolerances: distances are compared with tol = 1e-9 * S + 1e-12 * M, where S is the half
// diagonal of the input part's bounding box and M its largest |coordinate|; volumes with 1e-6
// relative (cut vertices are rounded to doubles), areas and stored figures with 1e-9 relative.
// The concavity re-measure allows also 2 x internal::kInPlaneTolerance of the component's
// bounding-box diagonal: the measure counts a point that close to a hull plane as in it (single
// precision input is flat to no better), so it may store up to about that much less. Likewise an
// opening's vertices may lie internal::kInPlaneTolerance of the part's bounding-box diagonal off
// its components: the cut counts a vertex that close to its plane as on it and leaves it where
// it is, so a cap is planar only to within that distance, and the opening is the planar polygon.

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/internal/closed_shells.h"
#include "acd/internal/exact_rounding.h"
#include "acd/internal/in_plane_tolerance.h"
#include "acd/internal/problem_list.h"
#include "acd/internal/side_of_mesh.h"
#include "acd/mesh_measures.h"
#include "base/format.h"
#include "base/random.h"

namespace acdplan::acd {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using SideOf = internal::SideOfMesh<Mesh>;

constexpr double kRelative = 1e-9;        // Areas, stored figures, tau, distances (x S).
constexpr double kVolumeRelative = 1e-6;  // Volume sums (cut vertices are rounded).
constexpr double kNoise = 1e-12;          // Distances (x largest |coordinate|).
constexpr int kSamplesPerComponent = 16;
constexpr std::uint64_t kSeed = 0x3D3D3D3D;  // Samples are seeded per component index.

std::string Num(double v) { return FormatSignificant(v, 12); }

std::string Pt(const Eigen::Vector3d& p) {
  return "(" + Num(p.x()) + ", " + Num(p.y()) + ", " + Num(p.z()) + ")";
}

using internal::ProblemList;

using Key = std::array<double, 3>;
Key KeyOf(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

Eigen::Vector3d Corner(const TriangleMesh& mesh, Eigen::Index f, int k) {
  return mesh.vertices.row(mesh.triangles(f, k)).transpose();
}

// Empty when `mesh` is well formed (finite, >= 1 triangle, indices in range), else the rule.
std::string MeshFault(const TriangleMesh& mesh) {
  if (mesh.triangles.rows() == 0) return "has no triangle";
  if (!mesh.vertices.allFinite()) return "has a non-finite vertex";
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(f, k);
      if (v < 0 || v >= mesh.vertices.rows()) {
        return "triangle " + std::to_string(f) + ": index " + std::to_string(v) +
               " out of range [0, " + std::to_string(mesh.vertices.rows()) + ")";
      }
    }
  }
  return "";
}

// Vertex ids that identify vertices at equal positions.
std::vector<int> PositionIds(const TriangleMesh& mesh, int* count) {
  std::map<Key, int> ids;
  std::vector<int> out(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    out[static_cast<size_t>(v)] =
        ids.emplace(KeyOf(mesh.vertices.row(v).transpose()), static_cast<int>(ids.size()))
            .first->second;
  }
  *count = static_cast<int>(ids.size());
  return out;
}

// Empty when every directed edge (vertices by position) has exactly one opposite and occurs
// once: closed and consistently oriented. Else the first offending edge.
// With `manifold` false, a directed edge may occur several times as long as its reverse occurs
// as often (a flat hull covers its polygon from both sides).
std::string ClosedFault(const TriangleMesh& mesh, bool manifold) {
  int count = 0;
  const std::vector<int> id = PositionIds(mesh, &count);
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = id[static_cast<size_t>(mesh.triangles(f, k))];
      const int b = id[static_cast<size_t>(mesh.triangles(f, (k + 1) % 3))];
      if (a == b) return "triangle " + std::to_string(f) + " has two corners at one position";
      ++directed[{a, b}];
    }
  }
  for (const auto& [edge, n] : directed) {
    const auto it = directed.find({edge.second, edge.first});
    const int opposite = it == directed.end() ? 0 : it->second;
    if (manifold ? n == 1 && opposite == 1 : n == opposite) continue;
    // Report with positions (the first vertex of each id).
    Eigen::Vector3d pa = Eigen::Vector3d::Zero(), pb = pa;
    for (size_t v = 0; v < id.size(); ++v) {
      if (id[v] == edge.first) pa = mesh.vertices.row(static_cast<Eigen::Index>(v)).transpose();
      if (id[v] == edge.second) pb = mesh.vertices.row(static_cast<Eigen::Index>(v)).transpose();
    }
    if (opposite == 0) return "edge " + Pt(pa) + "-" + Pt(pb) + " has no opposite (open)";
    return "edge " + Pt(pa) + "-" + Pt(pb) + " occurs " + std::to_string(n) + " times and " +
           std::to_string(opposite) + " times reversed (not a consistently oriented 2-manifold)";
  }
  return "";
}

// A CGAL mesh of `mesh` (vertices merged by position); nullopt if a face cannot be added
// (non-manifold or inconsistently oriented).
std::optional<Mesh> ToCgal(const TriangleMesh& mesh) {
  int count = 0;
  const std::vector<int> id = PositionIds(mesh, &count);
  Mesh out;
  std::vector<Mesh::Vertex_index> vertex(static_cast<size_t>(count));
  std::vector<bool> added(static_cast<size_t>(count), false);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const int i = id[static_cast<size_t>(v)];
    if (added[static_cast<size_t>(i)]) continue;
    added[static_cast<size_t>(i)] = true;
    vertex[static_cast<size_t>(i)] =
        out.add_vertex(Point3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)));
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Mesh::Face_index face =
        out.add_face(vertex[static_cast<size_t>(id[static_cast<size_t>(mesh.triangles(f, 0))])],
                     vertex[static_cast<size_t>(id[static_cast<size_t>(mesh.triangles(f, 1))])],
                     vertex[static_cast<size_t>(id[static_cast<size_t>(mesh.triangles(f, 2))])]);
    if (face == Mesh::null_face()) return std::nullopt;
  }
  return out;
}

// Largest distance of a vertex or face centroid of `mesh` to the boundary of the convex hull of
// its vertices, from below. Each hull facet's plane is taken with the rounding of its normal (its
// cross product's error over its length) times the hull's diameter subtracted: a plane turned by
// that much measures a point's distance off by at most that. A facet whose normal is all
// rounding bounds nothing, and neither does a flat hull (exactly, as ConvexHull3 decides): every
// point of a flat set is on its hull's boundary. Without the error terms the bound was none for a
// needle: four corners 1e30 apart and 1e13 off a line (fuzz/corpus/decompose3d/
// regression-needle-hull-at-1e30.bin) gave hull planes whose normals were noise, which put a face
// centroid 1.1e28 deep; the same for a needle triangle at 4e30, 6.6e28 below its plane
// (regression-needle-patch-at-4e30.bin).
double ConcavityLowerBound(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<size_t>(mesh.vertices.rows() + mesh.triangles.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    points.push_back(mesh.vertices.row(v).transpose());
  }
  const TriangleMesh hull = ConvexHull3(points, 0.0);
  if (IsFlatHull(hull)) return 0.0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    points.push_back((Corner(mesh, f, 0) + Corner(mesh, f, 1) + Corner(mesh, f, 2)) / 3.0);
  }
  const Eigen::AlignedBox3d box = BoundingBox(hull);
  const double magnitude =
      std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  const double diameter = box.diagonal().norm();
  constexpr double kUlp = std::numeric_limits<double>::epsilon();
  struct Plane {
    Eigen::Vector3d normal;
    double offset, error;  // the hull lies in normal . x <= offset; depths err by up to error
  };
  std::vector<Plane> planes;
  for (Eigen::Index f = 0; f < hull.triangles.rows(); ++f) {
    const Eigen::Vector3d a = Corner(hull, f, 0);
    const Eigen::Vector3d u = Corner(hull, f, 1) - a, w = Corner(hull, f, 2) - a;
    Eigen::Vector3d normal = u.cross(w);
    const double length = normal.norm();
    // Rounding of u and w (an ulp of the coordinates each) and of the products, with room.
    const double normal_error =
        16 * kUlp * (u.norm() * w.norm() + magnitude * (u.norm() + w.norm()));
    if (!(length > normal_error)) return 0.0;
    normal /= length;
    double offset = -std::numeric_limits<double>::infinity();
    for (Eigen::Index v = 0; v < hull.vertices.rows(); ++v) {
      offset = std::max(offset, normal.dot(hull.vertices.row(v).transpose()));
    }
    planes.push_back({normal, offset, 2 * normal_error / length * diameter + 8 * kUlp * magnitude});
  }
  double best = 0.0;
  for (const Eigen::Vector3d& p : points) {
    double depth = std::numeric_limits<double>::infinity();
    for (size_t r = 0; r < planes.size() && depth > best; ++r) {
      depth = std::min(depth, planes[r].offset - planes[r].normal.dot(p) - planes[r].error);
    }
    best = std::max(best, depth);
  }
  return best;
}

// How far `p` lies outside the closed convex mesh `hull`: 0 when no facet has `p` strictly on
// its outer side (exact orientation), else the largest exact distance to such a facet's plane.
double ExactHullExcess(const TriangleMesh& hull, const Eigen::Vector3d& p) {
  using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
  const Point3 q(p.x(), p.y(), p.z());
  double excess = 0.0;
  for (Eigen::Index f = 0; f < hull.triangles.rows(); ++f) {
    const Eigen::Vector3d a = Corner(hull, f, 0), b = Corner(hull, f, 1), c = Corner(hull, f, 2);
    const Point3 pa(a.x(), a.y(), a.z()), pb(b.x(), b.y(), b.z()), pc(c.x(), c.y(), c.z());
    // Outside a face counter-clockwise seen from outside: (b - a) x (c - a) . (q - a) > 0.
    if (CGAL::collinear(pa, pb, pc) || CGAL::orientation(pa, pb, pc, q) != CGAL::POSITIVE) {
      continue;
    }
    const Exact::Plane_3 plane(Exact::Point_3(a.x(), a.y(), a.z()),
                               Exact::Point_3(b.x(), b.y(), b.z()),
                               Exact::Point_3(c.x(), c.y(), c.z()));
    const double d2 =
        internal::RoundToDouble(CGAL::squared_distance(plane, Exact::Point_3(p.x(), p.y(), p.z())));
    excess = std::max(excess, std::sqrt(d2));
  }
  return excess;
}

// Newell's normal (length = twice the area) of a closed polygon.
Eigen::Vector3d NewellNormal(const std::vector<Eigen::Vector3d>& polygon) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < polygon.size(); ++i) {
    n += (polygon[i] - polygon[0]).cross(polygon[(i + 1) % polygon.size()] - polygon[0]);
  }
  return n;
}

// The lengths of the faces' edges, an edge shared by two faces counted twice.
double EdgeLengthSum(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) sum += (Corner(mesh, f, (k + 1) % 3) - Corner(mesh, f, k)).norm();
  }
  return sum;
}

bool Near(double a, double b, double relative, double absolute) {
  return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + absolute;
}

class Checker {
 public:
  Checker(const PreparedMesh& input, const Decomposition3d& d)
      : input_(input), d_(d), surface_(d.stats.surface) {}

  std::vector<std::string> Run() && {
    CheckParts();
    CheckTree();
    CheckComponents();
    if (surface_) {
      CheckPatchesPartitionFaces();
    } else {
      CheckVolumes();
      CheckInteriors();
    }
    CheckOpenings();
    CheckStats();
    return std::move(problems_).Finish();
  }

 private:
  struct PartInfo {
    double tolerance = 0.0;
    double scale = 0.0;  // Half diagonal of the bounding box.
    std::unique_ptr<Mesh> mesh;
    std::unique_ptr<SideOf> side;
    std::unique_ptr<Tree> tree;
  };
  struct ComponentInfo {
    bool usable = false;    // Well formed, from an existing part.
    bool solid_ok = false;  // Closed, outward, no self-intersection (solid ACD).
    std::unique_ptr<Mesh> mesh;
    std::unique_ptr<SideOf> side;
    std::unique_ptr<Tree> tree;
    Eigen::AlignedBox3d box;
  };

  int Count() const { return static_cast<int>(d_.components.size()); }
  std::string Name(int i) const { return "component " + std::to_string(i) + ": "; }

  void CheckParts() {
    parts_.resize(input_.parts.size());
    for (size_t p = 0; p < input_.parts.size(); ++p) {
      const TriangleMesh& part = input_.parts[p];
      const Eigen::AlignedBox3d box = BoundingBox(part);
      const double max_abs = part.vertices.rows() > 0 ? part.vertices.cwiseAbs().maxCoeff() : 0.0;
      parts_[p].scale = part.vertices.rows() > 0 ? 0.5 * box.diagonal().norm() : 0.0;
      parts_[p].tolerance = kRelative * parts_[p].scale + kNoise * max_abs;
    }
    if (!surface_ && !input_.solid()) {
      problems_.Add("the input is not a solid (" + input_.defects.first +
                    ") but the solid ACD was used");
    }
  }

  void CheckTree() {
    const int nodes = static_cast<int>(d_.tree.size());
    if (d_.roots.size() != input_.parts.size()) {
      problems_.Add(std::to_string(d_.roots.size()) + " roots for " +
                    std::to_string(input_.parts.size()) + " parts");
    }
    std::vector<int> leaf_of(d_.components.size(), -1);
    for (int n = 0; n < nodes; ++n) {
      const HierarchyNode3d& node = d_.tree[static_cast<size_t>(n)];
      const std::string label = "tree node " + std::to_string(n) + ": ";
      for (int c : node.children) {
        if (c <= n || c >= nodes || d_.tree[static_cast<size_t>(c)].parent != n) {
          problems_.Add(label + "child " + std::to_string(c) + " is not a node whose parent it is");
        }
      }
      if (node.children.empty()) {
        // Several leaves share a component that the merge pass united (MergeComponents()).
        if (node.component < 0 || node.component >= Count()) {
          problems_.Add(label + "leaf without a component (" + std::to_string(node.component) +
                        ")");
        } else if (leaf_of[static_cast<size_t>(node.component)] < 0) {
          leaf_of[static_cast<size_t>(node.component)] = n;
        }
      } else if (node.children.size() < 2) {
        problems_.Add(label + "an internal node with one child");
      }
    }
    for (int c = 0; c < Count(); ++c) {
      if (leaf_of[static_cast<size_t>(c)] < 0 && nodes > 0) {
        problems_.Add(Name(c) + "is the leaf of no tree node");
      }
    }
  }

  void CheckComponents() {
    info_.resize(d_.components.size());
    for (int i = 0; i < Count(); ++i) {
      const Component3d& c = d_.components[static_cast<size_t>(i)];
      ComponentInfo& info = info_[static_cast<size_t>(i)];
      if (c.source < 0 || c.source >= static_cast<int>(input_.parts.size())) {
        problems_.Add(Name(i) + "source " + std::to_string(c.source) + " is not a part index");
        continue;
      }
      if (const std::string fault = MeshFault(c.mesh); !fault.empty()) {
        problems_.Add(Name(i) + "mesh " + fault);
        continue;
      }
      if (const std::string fault = MeshFault(c.hull); !fault.empty()) {
        problems_.Add(Name(i) + "hull " + fault);
        continue;
      }
      info.usable = true;
      info.box = BoundingBox(c.mesh);
      const PartInfo& part = parts_[static_cast<size_t>(c.source)];
      const double tol = part.tolerance;
      const double volume_unit = part.scale * part.scale * part.scale;

      // Hull: closed, containing the mesh.
      if (const std::string fault = ClosedFault(c.hull, false); !fault.empty()) {
        problems_.Add(Name(i) + "hull is not closed: " + fault);
      }
      const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = HullPlanes(c.hull);
      double outside = 0.0;
      Eigen::Vector3d worst = Eigen::Vector3d::Zero();
      for (Eigen::Index v = 0; v < c.mesh.vertices.rows(); ++v) {
        const Eigen::Vector3d p = c.mesh.vertices.row(v).transpose();
        double excess = 0.0;
        for (Eigen::Index r = 0; r < planes.rows(); ++r) {
          excess = std::max(excess, planes.row(r).head<3>().dot(p) - planes(r, 3));
        }
        // A sliver hull facet has a badly rounded plane: confirm exactly before reporting.
        if (excess > tol) excess = ExactHullExcess(c.hull, p);
        if (excess > outside) {
          outside = excess;
          worst = p;
        }
      }
      if (outside > tol) {
        problems_.Add(Name(i) + "vertex " + Pt(worst) + " lies outside the hull (by " +
                      Num(outside) + ")");
      }

      // Stored figures.
      const double volume = surface_ ? 0.0 : MeshVolume(c.mesh);
      if (!Near(c.volume, volume, kRelative, kRelative * kRelative * volume_unit)) {
        problems_.Add(Name(i) + "volume " + Num(c.volume) + " != " + Num(volume) +
                      (surface_ ? " (a surface patch)" : " (MeshVolume)"));
      }
      const double hull_volume = MeshVolume(c.hull);
      if (!Near(c.hull_volume, hull_volume, kRelative, kRelative * kRelative * volume_unit)) {
        problems_.Add(Name(i) + "hull_volume " + Num(c.hull_volume) + " != " + Num(hull_volume));
      }
      const Eigen::Vector3d centroid = MeshCentroid(c.mesh, !surface_);
      if (!((c.centroid - centroid).norm() <= tol + kRelative * centroid.norm())) {
        problems_.Add(Name(i) + "centroid " + Pt(c.centroid) + " != " + Pt(centroid) +
                      (surface_ ? " (area centroid)" : " (volume centroid)"));
      }

      // Concavity: lower bound re-measured against tau and against the stored value.
      const double lower = ConcavityLowerBound(c.mesh);
      const double in_plane =
          2 * internal::kInPlaneTolerance * info.box.diagonal().norm();  // see the top
      if (!(c.concavity >= lower - tol - in_plane - kRelative * lower)) {
        problems_.Add(Name(i) + "concavity " + Num(c.concavity) +
                      " is below its re-measured lower bound " + Num(lower));
      }
      if (d_.max_hulls == 0) {
        const double limit = d_.tau * (1.0 + kRelative) + tol;
        if (!(c.concavity <= limit)) {
          problems_.Add(Name(i) + "concavity " + Num(c.concavity) + " > tau " + Num(d_.tau));
        } else if (!(lower <= limit + in_plane)) {
          problems_.Add(Name(i) + "re-measured concavity " + Num(lower) + " > tau " + Num(d_.tau) +
                        " (distance of a vertex or face centroid to the hull boundary)");
        }
      }

      if (surface_) continue;
      // Solid: closed, outward, no self-intersection.
      if (const std::string fault = ClosedFault(c.mesh, true); !fault.empty()) {
        problems_.Add(Name(i) + "mesh is not closed: " + fault);
        continue;
      }
      // The exact sign: a sliver's rounded volume may have either.
      if (internal::VolumeSign(c.mesh) <= 0) {
        problems_.Add(Name(i) + "mesh is inward-oriented (volume " + Num(volume) + ")");
        continue;
      }
      std::optional<Mesh> mesh = ToCgal(c.mesh);
      if (!mesh) {
        problems_.Add(Name(i) + "mesh is not a 2-manifold (CGAL rejects a face)");
        continue;
      }
      if (CGAL::Polygon_mesh_processing::does_self_intersect(*mesh)) {
        problems_.Add(Name(i) + "mesh self-intersects");
        continue;
      }
      info.mesh = std::make_unique<Mesh>(std::move(*mesh));
      info.side = std::make_unique<SideOf>(*info.mesh);
      info.solid_ok = true;
    }
  }

  void CheckVolumes() {
    std::vector<double> sums(input_.parts.size(), 0.0);
    for (const Component3d& c : d_.components) {
      if (c.source >= 0 && c.source < static_cast<int>(sums.size())) {
        sums[static_cast<size_t>(c.source)] += MeshVolume(c.mesh);
      }
    }
    for (size_t p = 0; p < input_.parts.size(); ++p) {
      const double volume = MeshVolume(input_.parts[p]);
      // Besides the relative bound, a layer as thick as the distance tolerance over the part's
      // surface: a near-flat part's volume is rounding noise, which no relative bound covers.
      const double layer = parts_[p].tolerance * MeshArea(input_.parts[p]);
      if (!Near(sums[p], volume, kVolumeRelative, layer)) {
        problems_.Add("part " + std::to_string(p) + ": component volumes sum to " + Num(sums[p]) +
                      ", the part's volume is " + Num(volume) +
                      (sums[p] < volume ? " (a gap)" : " (an overlap)"));
      }
    }
  }

  PartInfo& PartTrees(int p) {
    PartInfo& part = parts_[static_cast<size_t>(p)];
    if (!part.mesh) {
      std::optional<Mesh> mesh = ToCgal(input_.parts[static_cast<size_t>(p)]);
      part.mesh = std::make_unique<Mesh>(mesh ? std::move(*mesh) : Mesh());
      part.side = std::make_unique<SideOf>(*part.mesh);
      part.tree =
          std::make_unique<Tree>(faces(*part.mesh).first, faces(*part.mesh).second, *part.mesh);
      part.tree->accelerate_distance_queries();
    }
    return part;
  }

  // Seeded points just inside each component: inside no other, not outside the part.
  void CheckInteriors() {
    std::set<std::pair<int, int>> reported;
    for (int i = 0; i < Count(); ++i) {
      const ComponentInfo& info = info_[static_cast<size_t>(i)];
      if (!info.solid_ok) continue;
      const Component3d& c = d_.components[static_cast<size_t>(i)];
      PartInfo& part = PartTrees(c.source);
      if (part.mesh->number_of_faces() == 0) continue;
      // Vertices: outside the part only within the tolerance.
      for (Eigen::Index v = 0; v < c.mesh.vertices.rows(); ++v) {
        const Point3 p(c.mesh.vertices(v, 0), c.mesh.vertices(v, 1), c.mesh.vertices(v, 2));
        if ((*part.side)(p) != CGAL::ON_UNBOUNDED_SIDE) continue;
        const double distance = std::sqrt(part.tree->squared_distance(p));
        if (distance > part.tolerance) {
          problems_.Add(Name(i) + "vertex " + Pt(c.mesh.vertices.row(v).transpose()) +
                        " lies outside the input part (by " + Num(distance) + ")");
          break;
        }
      }
      RandomEngine rng(DeriveSeed(kSeed, static_cast<std::uint64_t>(i)));
      const double area = MeshArea(c.mesh);
      const double step = 1e-4 * info.box.diagonal().norm();
      for (int s = 0; s < kSamplesPerComponent; ++s) {
        // A face by area, a point on it, a step inward.
        double pick = UniformReal(rng, 0.0, area);
        Eigen::Index f = 0;
        for (; f + 1 < c.mesh.triangles.rows(); ++f) {
          const double a = 0.5 * (Corner(c.mesh, f, 1) - Corner(c.mesh, f, 0))
                                     .cross(Corner(c.mesh, f, 2) - Corner(c.mesh, f, 0))
                                     .norm();
          if (pick < a) break;
          pick -= a;
        }
        double u = UniformReal(rng, 0.0, 1.0), w = UniformReal(rng, 0.0, 1.0);
        if (u + w > 1.0) u = 1.0 - u, w = 1.0 - w;
        const Eigen::Vector3d a = Corner(c.mesh, f, 0), b = Corner(c.mesh, f, 1),
                              cc = Corner(c.mesh, f, 2);
        const Eigen::Vector3d normal = (b - a).cross(cc - a);
        if (!(normal.norm() > 0)) continue;
        const Eigen::Vector3d x = a + u * (b - a) + w * (cc - a) - step * normal.normalized();
        const Point3 q(x.x(), x.y(), x.z());
        if ((*info.side)(q) != CGAL::ON_BOUNDED_SIDE) continue;  // A thin spot: no witness.
        if ((*part.side)(q) == CGAL::ON_UNBOUNDED_SIDE &&
            std::sqrt(part.tree->squared_distance(q)) > part.tolerance) {
          problems_.Add(Name(i) + "interior point " + Pt(x) + " lies outside the input part");
        }
        for (int j = 0; j < Count(); ++j) {
          const ComponentInfo& other = info_[static_cast<size_t>(j)];
          if (j == i || !other.solid_ok || d_.components[static_cast<size_t>(j)].source != c.source)
            continue;
          if (!other.box.contains(x)) continue;
          if ((*other.side)(q) != CGAL::ON_BOUNDED_SIDE) continue;
          if (reported.insert({std::min(i, j), std::max(i, j)}).second) {
            problems_.Add("components " + std::to_string(i) + " and " + std::to_string(j) +
                          " overlap: " + Pt(x) + " is inside both");
          }
        }
      }
    }
  }

  // Surface ACD: the patches' faces are the part's faces, each exactly once.
  void CheckPatchesPartitionFaces() {
    using FaceKey = std::array<Key, 3>;
    auto face_key = [](const TriangleMesh& m, Eigen::Index f) {
      FaceKey key = {KeyOf(Corner(m, f, 0)), KeyOf(Corner(m, f, 1)), KeyOf(Corner(m, f, 2))};
      std::sort(key.begin(), key.end());
      return key;
    };
    std::vector<std::map<FaceKey, int>> remaining(input_.parts.size());  // key -> unused count
    std::vector<double> part_area(input_.parts.size(), 0.0), patch_area(input_.parts.size(), 0.0);
    for (size_t p = 0; p < input_.parts.size(); ++p) {
      for (Eigen::Index f = 0; f < input_.parts[p].triangles.rows(); ++f) {
        ++remaining[p][face_key(input_.parts[p], f)];
      }
      part_area[p] = MeshArea(input_.parts[p]);
    }
    for (int i = 0; i < Count(); ++i) {
      if (!info_[static_cast<size_t>(i)].usable) continue;
      const Component3d& c = d_.components[static_cast<size_t>(i)];
      const size_t p = static_cast<size_t>(c.source);
      patch_area[p] += MeshArea(c.mesh);
      for (Eigen::Index f = 0; f < c.mesh.triangles.rows(); ++f) {
        const auto it = remaining[p].find(face_key(c.mesh, f));
        if (it == remaining[p].end()) {
          problems_.Add(Name(i) + "triangle " + std::to_string(f) + " at " +
                        Pt(Corner(c.mesh, f, 0)) + " is not a face of part " + std::to_string(p));
        } else if (it->second == 0) {
          problems_.Add(Name(i) + "triangle " + std::to_string(f) + " at " +
                        Pt(Corner(c.mesh, f, 0)) + " is already in another patch");
        } else {
          --it->second;
        }
      }
    }
    for (size_t p = 0; p < input_.parts.size(); ++p) {
      int missing = 0;
      const FaceKey* first = nullptr;
      for (const auto& [key, n] : remaining[p]) {
        if (n > 0 && !first) first = &key;
        missing += n;
      }
      if (missing > 0) {
        problems_.Add("part " + std::to_string(p) + ": " + std::to_string(missing) +
                      " faces are in no patch, e.g. the one at (" + Num((*first)[0][0]) + ", " +
                      Num((*first)[0][1]) + ", " + Num((*first)[0][2]) + ")");
      }
      // Besides the relative bound, a band as wide as the distance tolerance along the part's
      // edges: a needle face's area is rounding noise, which no relative bound covers.
      const double band = parts_[p].tolerance * EdgeLengthSum(input_.parts[p]);
      if (!Near(patch_area[p], part_area[p], kRelative, band)) {
        problems_.Add("part " + std::to_string(p) + ": patch areas sum to " + Num(patch_area[p]) +
                      ", the part's area is " + Num(part_area[p]));
      }
    }
  }

  void CheckOpenings() {
    // Surface: the edges of each patch, by position.
    std::vector<std::set<std::pair<Key, Key>>> edges;
    if (surface_) {
      edges.resize(d_.components.size());
      for (int i = 0; i < Count(); ++i) {
        if (!info_[static_cast<size_t>(i)].usable) continue;
        const TriangleMesh& m = d_.components[static_cast<size_t>(i)].mesh;
        for (Eigen::Index f = 0; f < m.triangles.rows(); ++f) {
          for (int k = 0; k < 3; ++k) {
            Key a = KeyOf(Corner(m, f, k)), b = KeyOf(Corner(m, f, (k + 1) % 3));
            if (b < a) std::swap(a, b);
            edges[static_cast<size_t>(i)].insert({a, b});
          }
        }
      }
    }
    for (size_t o = 0; o < d_.openings.size(); ++o) {
      const Opening3d& opening = d_.openings[o];
      const std::string label = "opening " + std::to_string(o) + ": ";
      const int a = opening.component_a, b = opening.component_b;
      if (a < 0 || b >= Count() || !(a < b)) {
        problems_.Add(label + "components " + std::to_string(a) + ", " + std::to_string(b) +
                      " are not two component indices a < b");
        continue;
      }
      if (!info_[static_cast<size_t>(a)].usable || !info_[static_cast<size_t>(b)].usable) continue;
      const PartInfo& part =
          parts_[static_cast<size_t>(d_.components[static_cast<size_t>(a)].source)];
      const double tol = part.tolerance;
      if (surface_) {
        if (opening.polygon.size() < 2) {
          problems_.Add(label + "a polyline needs >= 2 vertices");
          continue;
        }
        if (opening.area != 0.0 || !opening.normal.isZero(0.0)) {
          problems_.Add(label + "a surface opening has area 0 and a zero normal");
        }
        if (!opening.holes.empty()) problems_.Add(label + "a surface opening has no holes");
        for (size_t k = 0; k + 1 < opening.polygon.size(); ++k) {
          Key p = KeyOf(opening.polygon[k]), q = KeyOf(opening.polygon[k + 1]);
          if (q < p) std::swap(p, q);
          for (int side : {a, b}) {
            if (!edges[static_cast<size_t>(side)].count({p, q})) {
              problems_.Add(label + "segment " + Pt(opening.polygon[k]) + "-" +
                            Pt(opening.polygon[k + 1]) + " is not an edge of component " +
                            std::to_string(side));
              k = opening.polygon.size();
              break;
            }
          }
        }
        continue;
      }
      if (opening.polygon.size() < 3) {
        problems_.Add(label + "a polygon needs >= 3 vertices");
        continue;
      }
      // The region's rings: the outline, then the holes (clockwise, so their Newell normals
      // subtract).
      std::vector<const std::vector<Eigen::Vector3d>*> rings = {&opening.polygon};
      for (const std::vector<Eigen::Vector3d>& hole : opening.holes) rings.push_back(&hole);
      const Eigen::Vector3d outline_newell = NewellNormal(opening.polygon);
      Eigen::Vector3d newell = Eigen::Vector3d::Zero();
      // The vertices are rounded to doubles: each may lie up to tol off, which moves the area
      // by up to tol x the perimeter (it matters for slivers of 1e-11 units^2).
      double perimeter = 0;
      for (size_t r = 0; r < rings.size(); ++r) {
        const std::vector<Eigen::Vector3d>& ring = *rings[r];
        const Eigen::Vector3d ring_newell = NewellNormal(ring);
        newell += ring_newell;
        for (size_t k = 0; k < ring.size(); ++k) {
          perimeter += (ring[(k + 1) % ring.size()] - ring[k]).norm();
        }
        if (r > 0 && (ring.size() < 3 || !(ring_newell.dot(outline_newell) < 0))) {
          problems_.Add(label + "hole " + std::to_string(r - 1) +
                        " is not a clockwise polygon about the normal");
        }
      }
      const double area = 0.5 * newell.norm();
      if (!Near(opening.area, area, 1e-6, tol * perimeter)) {
        problems_.Add(label + "area " + Num(opening.area) + " != polygon area " + Num(area));
      }
      if (area > 0 && !((opening.normal - newell.normalized()).norm() <= 1e-6)) {
        problems_.Add(label + "normal " + Pt(opening.normal) +
                      " is not the polygon's counter-clockwise normal " + Pt(newell.normalized()));
      }
      for (int side : {a, b}) {
        ComponentInfo& info = info_[static_cast<size_t>(side)];
        if (!info.solid_ok) continue;
        if (!info.tree) {
          info.tree =
              std::make_unique<Tree>(faces(*info.mesh).first, faces(*info.mesh).second, *info.mesh);
        }
        bool off = false;
        for (size_t r = 0; r < rings.size() && !off; ++r) {
          for (const Eigen::Vector3d& x : *rings[r]) {
            const double distance =
                std::sqrt(info.tree->squared_distance(Point3(x.x(), x.y(), x.z())));
            if (distance > tol + 2 * internal::kInPlaneTolerance * part.scale) {  // see the top
              problems_.Add(label + "vertex " + Pt(x) + " is not on the boundary of component " +
                            std::to_string(side) + " (distance " + Num(distance) + ")");
              off = true;
              break;
            }
          }
        }
      }
    }
  }

  void CheckStats() {
    const DecompositionStats3d& s = d_.stats;
    if (s.components != Count()) {
      problems_.Add("stats.components " + std::to_string(s.components) +
                    " != " + std::to_string(Count()) + " components");
    }
    double volume = 0.0, hull_volume = 0.0, max_concavity = 0.0;
    for (const Component3d& c : d_.components) {
      volume += c.volume;
      hull_volume += c.hull_volume;
      max_concavity = std::max(max_concavity, c.concavity);
    }
    if (!Near(s.volume, volume, kRelative, 0.0)) {
      problems_.Add("stats.volume " + Num(s.volume) + " != sum of volumes " + Num(volume));
    }
    if (!Near(s.hull_volume, hull_volume, kRelative, 0.0)) {
      problems_.Add("stats.hull_volume " + Num(s.hull_volume) + " != sum of hull volumes " +
                    Num(hull_volume));
    }
    if (!Near(s.max_concavity, max_concavity, kRelative, 0.0)) {
      problems_.Add("stats.max_concavity " + Num(s.max_concavity) +
                    " != largest component concavity " + Num(max_concavity));
    }
  }

  const PreparedMesh& input_;
  const Decomposition3d& d_;
  const bool surface_;
  std::vector<PartInfo> parts_;
  std::vector<ComponentInfo> info_;
  ProblemList problems_;
};

}  // namespace

DecompositionCheck CheckDecomposition3d(const PreparedMesh& input,
                                        const Decomposition3d& decomposition) {
  DecompositionCheck check;
  check.problems = Checker(input, decomposition).Run();
  return check;
}

}  // namespace acdplan::acd
