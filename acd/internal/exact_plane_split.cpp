#include "acd/internal/exact_plane_split.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include "acd/internal/closed_shells.h"
#include "acd/internal/disjoint_sets.h"
#include "acd/internal/exact_rounding.h"
#include "acd/internal/face_intersections.h"
#include "acd/internal/in_plane_tolerance.h"
#include "acd/internal/nesting_levels.h"
#include "acd/internal/separate_pinches.h"

namespace acdplan::acd::internal {
namespace {

using FT = ExactKernel::FT;
using Point3 = ExactKernel::Point_3;
using Tri = std::array<int, 3>;

struct FaceInfo {
  int nesting = -1;
};
// A section vertex's index; -1 for a point the triangulation made where constraints cross.
struct VertexId {
  int id = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, ExactKernel>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, ExactKernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<ExactKernel, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Section loops of a valid solid meet at most in vertices; the exact tag keeps the
// triangulation valid even if rounding-free inputs were to make two of them cross.
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<ExactKernel, Tds, CGAL::Exact_intersections_tag>;

// Each edge of `triangles` as (a, b, face) with a < b, sorted: the faces of an edge are one run.
using EdgeFace = std::array<int, 3>;
std::vector<EdgeFace> SortedEdgeFaces(const std::vector<Tri>& triangles) {
  std::vector<EdgeFace> out;
  out.reserve(3 * triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f) {
    for (size_t k = 0; k < 3; ++k) {
      const int a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      out.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f)});
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Calls `visit(begin, end)` for each edge's run [begin, end) of `edge_faces` (SortedEdgeFaces).
template <class Visit>
void ForEachEdge(const std::vector<EdgeFace>& edge_faces, Visit visit) {
  for (size_t i = 0, j = 0; i < edge_faces.size(); i = j) {
    while (j < edge_faces.size() && edge_faces[j][0] == edge_faces[i][0] &&
           edge_faces[j][1] == edge_faces[i][1]) {
      ++j;
    }
    visit(i, j);
  }
}

// Whether each edge's run of `edge_faces` (SortedEdgeFaces(triangles)) is two faces that run
// along it in opposite directions.
bool IsClosedAlong(const std::vector<Tri>& triangles, const std::vector<EdgeFace>& edge_faces) {
  // Whether triangle f runs from a to b.
  auto forward = [&](int f, int a, int b) {
    const Tri& t = triangles[static_cast<size_t>(f)];
    return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
  };
  bool closed = true;
  ForEachEdge(edge_faces, [&](size_t begin, size_t end) {
    const EdgeFace& e = edge_faces[begin];
    closed = closed && end - begin == 2 &&
             forward(e[2], e[0], e[1]) != forward(edge_faces[begin + 1][2], e[0], e[1]);
  });
  return closed;
}

// Labels each triangle with its shell (edge-connected set), numbered by smallest triangle.
// Only edges with exactly two faces join: two lobes touching along an edge (a cut through
// the edge where they meet) stay apart. `edge_faces`: SortedEdgeFaces(triangles).
std::vector<int> ShellLabels(const std::vector<Tri>& triangles,
                             const std::vector<EdgeFace>& edge_faces, int* count) {
  const int n = static_cast<int>(triangles.size());
  DisjointSets uf(n);
  ForEachEdge(edge_faces, [&](size_t begin, size_t end) {
    if (end - begin == 2) uf.Unite(edge_faces[begin][2], edge_faces[begin + 1][2]);
  });
  std::vector<int> label(static_cast<size_t>(n), -1), root_label(static_cast<size_t>(n), -1);
  *count = 0;
  for (int f = 0; f < n; ++f) {
    int& root = root_label[static_cast<size_t>(uf.Find(f))];
    if (root < 0) root = (*count)++;
    label[static_cast<size_t>(f)] = root;
  }
  return label;
}

// The piece made of `triangles` over `points`, with only the vertices it uses.
ExactPiece Compact(const std::vector<Point3>& points, const std::vector<Eigen::Vector3d>& rounded,
                   const std::vector<Tri>& triangles) {
  ExactPiece out;
  std::vector<int> index(points.size(), -1);
  out.triangles.reserve(triangles.size());
  for (const Tri& t : triangles) {
    Tri u;
    for (int k = 0; k < 3; ++k) {
      int& slot = index[static_cast<size_t>(t[static_cast<size_t>(k)])];
      if (slot < 0) {
        slot = static_cast<int>(out.points.size());
        out.points.push_back(points[static_cast<size_t>(t[static_cast<size_t>(k)])]);
        out.rounded.push_back(rounded[static_cast<size_t>(t[static_cast<size_t>(k)])]);
      }
      u[static_cast<size_t>(k)] = slot;
    }
    out.triangles.push_back(u);
  }
  return out;
}

// Gives each extra fan of faces around a vertex its own copy of the vertex, so a solid that
// touches itself in a vertex (a plane tangent there) has a manifold surface.
void SplitPinchedVertices(ExactPiece* piece) {
  std::vector<std::vector<int>> around(piece->points.size());
  for (size_t f = 0; f < piece->triangles.size(); ++f) {
    for (const int v : piece->triangles[f])
      around[static_cast<size_t>(v)].push_back(static_cast<int>(f));
  }
  const size_t original = piece->points.size();
  std::vector<int> fan;
  for (size_t v = 0; v < original; ++v) {
    const int fans = FansAroundVertex(piece->triangles, around[v], static_cast<int>(v), &fan);
    if (fans < 2) continue;
    std::vector<int> copy(static_cast<size_t>(fans), -1);  // fan -> its vertex
    copy[0] = static_cast<int>(v);
    for (size_t i = 0; i < around[v].size(); ++i) {
      int& c = copy[static_cast<size_t>(fan[i])];
      if (c < 0) {
        c = static_cast<int>(piece->points.size());
        piece->points.push_back(piece->points[v]);
        piece->rounded.push_back(piece->rounded[v]);
      }
      for (int& w : piece->triangles[static_cast<size_t>(around[v][i])]) {
        if (w == static_cast<int>(v)) w = c;
      }
    }
  }
}

FT Coordinate(const Point3& p, int axis) { return axis == 0 ? p.x() : (axis == 1 ? p.y() : p.z()); }

// The cap closing `below`'s section: the region bounded by the boundary edges of `below`
// (all in `plane`), triangulated with outward normal +n (seen from `below`). Nothing when a
// vertex or an edge of `in_plane` (the piece's, counted as on the plane: (v, v) for a vertex,
// (a, b) with a < b for an edge) that is not on the section's border lies in the section or on
// its border: there the plane touches the surface without crossing it (the bottom of a dimple
// or of a groove, the plane tangent to it), and the cap would pass through it, or within
// kInPlaneTolerance of it, leaving a piece that touches itself.
std::optional<std::vector<Tri>> SectionCap(const std::vector<Tri>& below,
                                           const ExactKernel::Plane_3& plane,
                                           const std::vector<std::pair<int, int>>& in_plane,
                                           std::vector<Point3>* points,
                                           std::vector<Eigen::Vector3d>* rounded) {
  std::map<std::pair<int, int>, int> net;  // +1 per a->b with a < b, -1 per b->a
  for (const Tri& t : below) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<size_t>(k)], b = t[static_cast<size_t>((k + 1) % 3)];
      if (a < b) {
        ++net[{a, b}];
      } else {
        --net[{b, a}];
      }
    }
  }
  std::vector<std::pair<int, int>> border;
  for (const auto& [edge, count] : net) {
    if (count != 0) border.push_back(edge);
  }
  if (border.empty()) return std::vector<Tri>{};
  // Project by dropping the coordinate the normal is largest along (exact: a coordinate copy);
  // cyclic order of the kept axes makes counter-clockwise mean a +axis normal.
  const std::array<FT, 3> coef = {plane.a(), plane.b(), plane.c()};
  int drop = 0;
  double best = -1;
  for (int k = 0; k < 3; ++k) {
    const double c = std::abs(RoundToDouble(coef[static_cast<size_t>(k)]));
    if (c > best) best = c, drop = k;
  }
  const int u_axis = (drop + 1) % 3, v_axis = (drop + 2) % 3;
  Cdt cdt;
  std::map<int, Cdt::Vertex_handle> handle;
  auto insert = [&](int id) {
    auto it = handle.find(id);
    if (it != handle.end()) return it->second;
    const Point3& p = (*points)[static_cast<size_t>(id)];
    Cdt::Vertex_handle vh =
        cdt.insert(ExactKernel::Point_2(Coordinate(p, u_axis), Coordinate(p, v_axis)));
    vh->info().id = id;
    handle.emplace(id, vh);
    return vh;
  };
  for (const auto& [a, b] : border) {
    Cdt::Vertex_handle va = insert(a), vb = insert(b);
    if (va != vb) cdt.insert_constraint(va, vb);
  }
  // Faces at odd nesting levels are inside the section.
  MarkNestingLevels(cdt);
  auto inside = [&](Cdt::Face_handle f) {
    return !cdt.is_infinite(f) && f->info().nesting % 2 == 1;
  };
  for (const auto& [a, b] : in_plane) {
    const bool on_border = a == b
                               ? handle.count(a) != 0
                               : std::binary_search(border.begin(), border.end(), std::pair{a, b});
    if (on_border) continue;
    const Point3& pa = (*points)[static_cast<size_t>(a)];
    const Point3 p = a == b ? pa : CGAL::midpoint(pa, (*points)[static_cast<size_t>(b)]);
    Cdt::Locate_type type;
    int li = 0;
    const Cdt::Face_handle f =
        cdt.locate(ExactKernel::Point_2(Coordinate(p, u_axis), Coordinate(p, v_axis)), type, li);
    // On a vertex of the border (where another vertex lies, or where border edges cross), it
    // touches the border.
    if (type == Cdt::VERTEX || (type == Cdt::FACE && inside(f)) ||
        (type == Cdt::EDGE && (inside(f) || inside(f->neighbor(li))))) {
      return std::nullopt;
    }
  }
  const bool flip = CGAL::is_negative(coef[static_cast<size_t>(drop)]);
  std::vector<Tri> cap;
  for (auto f : cdt.finite_face_handles()) {
    if (f->info().nesting % 2 != 1) continue;
    Tri t;
    for (int i = 0; i < 3; ++i) {
      Cdt::Vertex_handle vh = f->vertex(i);
      if (vh->info().id < 0) {  // a crossing of two constraints: lift it back onto the plane
        const FT u = vh->point().x(), v = vh->point().y();
        std::array<FT, 3> xyz;
        xyz[static_cast<size_t>(u_axis)] = u;
        xyz[static_cast<size_t>(v_axis)] = v;
        xyz[static_cast<size_t>(drop)] = -(coef[static_cast<size_t>(u_axis)] * u +
                                           coef[static_cast<size_t>(v_axis)] * v + plane.d()) /
                                         coef[static_cast<size_t>(drop)];
        vh->info().id = static_cast<int>(points->size());
        points->emplace_back(xyz[0], xyz[1], xyz[2]);
        rounded->push_back(RoundToDouble(points->back()));
      }
      t[static_cast<size_t>(i)] = vh->info().id;
    }
    if (flip) std::swap(t[1], t[2]);
    cap.push_back(t);
  }
  return cap;
}

}  // namespace

ExactPiece ToExact(const TriangleMesh& mesh) {
  ExactPiece piece;
  piece.points.reserve(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    piece.points.emplace_back(mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2));
    piece.rounded.emplace_back(mesh.vertices.row(i));
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    piece.triangles.push_back({mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)});
  }
  return piece;
}

TriangleMesh ToDouble(const ExactPiece& piece) {
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(piece.points.size()), 3);
  for (size_t i = 0; i < piece.points.size(); ++i) {
    mesh.vertices.row(static_cast<Eigen::Index>(i)) = piece.rounded[i].transpose();
  }
  mesh.triangles.resize(static_cast<Eigen::Index>(piece.triangles.size()), 3);
  for (size_t f = 0; f < piece.triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      mesh.triangles(static_cast<Eigen::Index>(f), k) = piece.triangles[f][static_cast<size_t>(k)];
    }
  }
  return mesh;
}

bool SplitByPlane(const ExactPiece& piece, const ExactKernel::Plane_3& plane, ExactPiece* below,
                  ExactPiece* above) {
  *below = {};
  *above = {};
  std::vector<Point3> points = piece.points;
  std::vector<Eigen::Vector3d> rounded = piece.rounded;
  std::vector<int> side(points.size());
  // A vertex within kInPlaneTolerance of the plane (relative to the piece's size) counts as on
  // it. A cut along a face of a model stored in single precision passes a few 1e-9 from the
  // face's other vertices, which rounding left off its plane; classified exactly, they gave
  // edges of 1e-9 and slivers of 1e-10 (the cup turned off the axes fell into 63 components
  // instead of 17). A cut along a cap of an earlier cut, along a plane rounded a little
  // differently, did the same. Each vertex is classified once, so both halves and the cap agree
  // on the topology, and no vertex moves: the cap is planar to within the tolerance, and the
  // halves share it exactly. The rest is exact.
  Eigen::AlignedBox3d box;
  for (const auto& r : rounded) box.extend(r);
  const Eigen::Vector3d n(RoundToDouble(plane.a()), RoundToDouble(plane.b()),
                          RoundToDouble(plane.c()));
  const double snap = kInPlaneTolerance * box.diagonal().norm() * n.norm();
  const double offset = RoundToDouble(plane.d());
  std::vector<std::pair<int, int>> in_plane;  // vertices (v, v), then edges (a, b), a < b
  for (size_t i = 0; i < points.size(); ++i) {
    side[i] = std::abs(n.dot(rounded[i]) + offset) <= snap
                  ? 0
                  : static_cast<int>(plane.oriented_side(points[i]));
    if (side[i] == 0) in_plane.emplace_back(static_cast<int>(i), static_cast<int>(i));
  }
  for (const Tri& t : piece.triangles) {  // each edge once: it runs a -> b in one of its faces
    for (size_t k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < b && side[static_cast<size_t>(a)] == 0 && side[static_cast<size_t>(b)] == 0) {
        in_plane.emplace_back(a, b);
      }
    }
  }
  // Crossings are computed on the exact values directly: as lazy expressions they would be a
  // dozen nodes each, and CGAL 5.5 guards each node's first exact evaluation by std::call_once,
  // which costs a system call (on mite, a tenth of the solid ACD's time).
  using ExactFT = ExactKernel::Exact_kernel::FT;
  const ExactKernel::Exact_kernel::Plane_3& exact_plane = CGAL::exact(plane);
  auto height = [&](int i) -> ExactFT {  // a value, not an expression template of references
    const ExactKernel::Exact_kernel::Point_3& p = CGAL::exact(points[static_cast<size_t>(i)]);
    return exact_plane.a() * p.x() + exact_plane.b() * p.y() + exact_plane.c() * p.z() +
           exact_plane.d();
  };
  std::map<std::pair<int, int>, int> crossing;  // edge (a < b) -> its exact intersection point
  // Crossings that round to one double position are one vertex: on a needle triangle (two
  // corners 1e-17 apart) the plane crosses both long edges 1e-17 apart, and two distinct exact
  // points output as one position would leave a triangle with two corners there. Joining
  // them collapses the short edge between them (its triangles, now degenerate, are dropped
  // below), moving a point by less than a double's resolution; the halves stay closed.
  std::map<std::array<double, 3>, int> crossing_at;
  auto cross = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    auto it = crossing.find({a, b});
    if (it != crossing.end()) return it->second;
    const ExactFT ha = height(a), hb = height(b);
    const ExactFT t = ha / (ha - hb);
    const ExactKernel::Exact_kernel::Point_3& p = CGAL::exact(points[static_cast<size_t>(a)]);
    const ExactKernel::Exact_kernel::Point_3& q = CGAL::exact(points[static_cast<size_t>(b)]);
    const std::array<ExactFT, 3> xe = {p.x() + (q.x() - p.x()) * t, p.y() + (q.y() - p.y()) * t,
                                       p.z() + (q.z() - p.z()) * t};
    const Point3 x{FT(xe[0]), FT(xe[1]), FT(xe[2])};
    const Eigen::Vector3d r(RoundToDouble(xe[0]), RoundToDouble(xe[1]), RoundToDouble(xe[2]));
    auto [at, inserted] = crossing_at.emplace(std::array<double, 3>{r.x(), r.y(), r.z()},
                                              static_cast<int>(points.size()));
    if (inserted) {
      points.push_back(x);
      rounded.push_back(r);
      side.push_back(0);
    }
    crossing.emplace(std::make_pair(a, b), at->second);
    return at->second;
  };
  // Fans a clipped polygon, without the corners a joined crossing repeats.
  auto fan = [](std::vector<int> polygon, std::vector<Tri>* out) {
    std::vector<int> kept;
    for (size_t i = 0; i < polygon.size(); ++i) {
      if (polygon[i] != polygon[(i + 1) % polygon.size()]) kept.push_back(polygon[i]);
    }
    for (size_t i = 1; i + 1 < kept.size(); ++i) out->push_back({kept[0], kept[i], kept[i + 1]});
  };
  const ExactKernel::Vector_3 normal = plane.orthogonal_vector();
  std::vector<Tri> lower, upper;
  for (const Tri& t : piece.triangles) {
    const int sa = side[static_cast<size_t>(t[0])], sb = side[static_cast<size_t>(t[1])],
              sc = side[static_cast<size_t>(t[2])];
    const int lo = std::min({sa, sb, sc}), hi = std::max({sa, sb, sc});
    if (lo == 0 && hi == 0) {
      // In the plane: it bounds the side its solid lies on (its outward normal points away).
      const Point3& a = points[static_cast<size_t>(t[0])];
      const auto n = CGAL::cross_product(points[static_cast<size_t>(t[1])] - a,
                                         points[static_cast<size_t>(t[2])] - a);
      (CGAL::is_positive(n * normal) ? lower : upper).push_back(t);
      continue;
    }
    if (hi <= 0) {
      lower.push_back(t);
      continue;
    }
    if (lo >= 0) {
      upper.push_back(t);
      continue;
    }
    // The plane crosses the triangle: clip it into a convex polygon per side and fan it.
    std::vector<int> neg, pos;
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<size_t>(k)], b = t[static_cast<size_t>((k + 1) % 3)];
      const int s = side[static_cast<size_t>(a)], s_next = side[static_cast<size_t>(b)];
      if (s <= 0) neg.push_back(a);
      if (s >= 0) pos.push_back(a);
      if (s * s_next < 0) {
        const int x = cross(a, b);
        neg.push_back(x);
        pos.push_back(x);
      }
    }
    fan(std::move(neg), &lower);
    fan(std::move(pos), &upper);
  }
  const std::optional<std::vector<Tri>> cap = SectionCap(lower, plane, in_plane, &points, &rounded);
  if (!cap) return false;
  for (const Tri& t : *cap) {
    lower.push_back(t);
    upper.push_back({t[0], t[2], t[1]});
  }
  *below = Compact(points, rounded, lower);
  *above = Compact(points, rounded, upper);
  return true;
}

std::vector<ExactPiece> ConnectedSolids(const ExactPiece& piece) {
  int count = 0;
  const std::vector<int> label =
      ShellLabels(piece.triangles, SortedEdgeFaces(piece.triangles), &count);
  std::vector<std::vector<int>> shell_faces(static_cast<size_t>(count));
  for (size_t f = 0; f < piece.triangles.size(); ++f) {
    shell_faces[static_cast<size_t>(label[f])].push_back(static_cast<int>(f));
  }
  auto triangle = [&](int f) -> const Tri& { return piece.triangles[static_cast<size_t>(f)]; };
  if (count == 1) {
    ExactPiece out = piece;
    SplitPinchedVertices(&out);
    return {out};
  }
  const std::vector<Eigen::Vector3d>& v = piece.rounded;
  std::vector<double> volume(static_cast<size_t>(count), 0.0);
  for (int s = 0; s < count; ++s) {
    const Eigen::Vector3d& o =
        v[static_cast<size_t>(triangle(shell_faces[static_cast<size_t>(s)][0])[0])];
    for (const int f : shell_faces[static_cast<size_t>(s)]) {
      const Tri& t = triangle(f);
      volume[static_cast<size_t>(s)] +=
          (v[static_cast<size_t>(t[0])] - o)
              .dot((v[static_cast<size_t>(t[1])] - o).cross(v[static_cast<size_t>(t[2])] - o)) /
          6.0;
    }
  }
  // Each outer shell starts a solid; each cavity joins the smallest outer shell around it.
  // A shell is a cavity only if clearly inward: a sliver's rounding-level volume is not.
  double largest = 0;
  for (double x : volume) largest = std::max(largest, std::abs(x));
  for (double& x : volume) {
    if (x < 0 && -x <= 1e-9 * largest) x = 0;
  }
  std::vector<int> owner(static_cast<size_t>(count), -1);
  for (int s = 0; s < count; ++s) {
    if (volume[static_cast<size_t>(s)] >= 0) owner[static_cast<size_t>(s)] = s;
  }
  // Exactly (a cavity can lie within rounding of its shell, or touch it where a pinch was split);
  // only when there is a cavity, which few cuts leave.
  const bool any_cavity = std::count(owner.begin(), owner.end(), -1) > 0;
  const std::vector<std::vector<int>> enclosing =
      any_cavity ? EnclosingShells(ToDouble(piece), shell_faces)
                 : std::vector<std::vector<int>>(static_cast<size_t>(count));
  for (int s = 0; s < count; ++s) {
    if (owner[static_cast<size_t>(s)] >= 0) continue;
    int best = -1;
    for (const int o : enclosing[static_cast<size_t>(s)]) {
      if (volume[static_cast<size_t>(o)] < 0) continue;
      if (best < 0 || volume[static_cast<size_t>(o)] < volume[static_cast<size_t>(best)]) best = o;
    }
    owner[static_cast<size_t>(s)] = best < 0 ? s : best;
  }
  std::vector<ExactPiece> out;
  for (int s = 0; s < count; ++s) {
    if (owner[static_cast<size_t>(s)] != s) continue;
    std::vector<Tri> tris;
    for (int t = 0; t < count; ++t) {
      if (owner[static_cast<size_t>(t)] != s) continue;
      for (const int f : shell_faces[static_cast<size_t>(t)]) tris.push_back(triangle(f));
    }
    out.push_back(Compact(piece.points, piece.rounded, tris));
    SplitPinchedVertices(&out.back());
  }
  return out;
}

RoundedFaceSet::Key RoundedFaceSet::KeyOf(const ExactPiece& piece, const Tri& t) {
  std::array<std::array<double, 3>, 3> corners;
  for (size_t k = 0; k < 3; ++k) {
    const Eigen::Vector3d& q = piece.rounded[static_cast<size_t>(t[k])];
    corners[k] = {q.x(), q.y(), q.z()};
  }
  std::sort(corners.begin(), corners.end());
  Key key;
  for (size_t k = 0; k < 9; ++k) key[k] = corners[k / 3][k % 3];
  return key;
}

RoundedFaceSet::RoundedFaceSet(const ExactPiece& piece) {
  keys_.reserve(piece.triangles.size());
  for (const Tri& t : piece.triangles) keys_.push_back(KeyOf(piece, t));
  std::sort(keys_.begin(), keys_.end());
}

bool RoundedFaceSet::Contains(const ExactPiece& piece, const Tri& t) const {
  return std::binary_search(keys_.begin(), keys_.end(), KeyOf(piece, t));
}

bool RoundsToValidSolid(const ExactPiece& piece, const RoundedFaceSet* valid_source) {
  using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Inexact::Point_3>;
  Mesh mesh;
  std::map<std::array<double, 3>, Mesh::Vertex_index> by_position;
  std::vector<Mesh::Vertex_index> vertex;
  vertex.reserve(piece.rounded.size());
  for (const Eigen::Vector3d& p : piece.rounded) {
    auto [it, inserted] =
        by_position.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, Mesh::Vertex_index());
    if (inserted) it->second = mesh.add_vertex(Inexact::Point_3(p.x(), p.y(), p.z()));
    vertex.push_back(it->second);
  }
  for (const Tri& t : piece.triangles) {
    const Mesh::Vertex_index a = vertex[static_cast<size_t>(t[0])],
                             b = vertex[static_cast<size_t>(t[1])],
                             c = vertex[static_cast<size_t>(t[2])];
    if (a == b || b == c || c == a) return false;
    if (mesh.add_face(a, b, c) == Mesh::null_face()) return false;
  }
  if (!CGAL::is_closed(mesh)) return false;
  if (valid_source == nullptr) return !CGAL::Polygon_mesh_processing::does_self_intersect(mesh);
  // Only pairs with a fresh face can cross. They are tested on the faces over the merged
  // vertices, so that two faces with a corner at one position share that corner.
  std::vector<int> fresh;
  for (size_t f = 0; f < piece.triangles.size(); ++f) {
    if (!valid_source->Contains(piece, piece.triangles[f])) fresh.push_back(static_cast<int>(f));
  }
  if (fresh.empty()) return true;
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(mesh.number_of_vertices());
  for (const Mesh::Vertex_index v : mesh.vertices()) {
    const Inexact::Point_3& p = mesh.point(v);
    positions.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<Eigen::Vector3i> faces;
  faces.reserve(piece.triangles.size());
  for (const Tri& t : piece.triangles) {
    faces.emplace_back(static_cast<int>(vertex[static_cast<size_t>(t[0])]),
                       static_cast<int>(vertex[static_cast<size_t>(t[1])]),
                       static_cast<int>(vertex[static_cast<size_t>(t[2])]));
  }
  return !AnyFaceIntersects(MakeTriangleMesh(positions, faces), fresh);
}

bool IsClosedSurface(const std::vector<std::array<int, 3>>& triangles) {
  return IsClosedAlong(triangles, SortedEdgeFaces(triangles));
}

ShellTopology Topology(const std::vector<std::array<int, 3>>& triangles) {
  const std::vector<EdgeFace> edge_faces = SortedEdgeFaces(triangles);
  int count = 0;
  const std::vector<int> label = ShellLabels(triangles, edge_faces, &count);
  // The Euler characteristic V - E + F of each shell, its edges and vertices counted once.
  std::vector<int> chi(static_cast<size_t>(count), 0);
  for (const int s : label) ++chi[static_cast<size_t>(s)];
  std::vector<int> shells_of_edge;
  ForEachEdge(edge_faces, [&](size_t begin, size_t end) {
    shells_of_edge.clear();
    for (size_t i = begin; i < end; ++i) {
      shells_of_edge.push_back(label[static_cast<size_t>(edge_faces[i][2])]);
    }
    std::sort(shells_of_edge.begin(), shells_of_edge.end());
    shells_of_edge.erase(std::unique(shells_of_edge.begin(), shells_of_edge.end()),
                         shells_of_edge.end());
    for (const int s : shells_of_edge) --chi[static_cast<size_t>(s)];
  });
  std::vector<std::pair<int, int>> vertex_shells;  // (vertex, shell)
  vertex_shells.reserve(3 * triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f) {
    for (const int v : triangles[f]) vertex_shells.emplace_back(v, label[f]);
  }
  std::sort(vertex_shells.begin(), vertex_shells.end());
  vertex_shells.erase(std::unique(vertex_shells.begin(), vertex_shells.end()), vertex_shells.end());
  for (const auto& [v, s] : vertex_shells) ++chi[static_cast<size_t>(s)];
  ShellTopology out;
  out.shells = count;
  out.closed = IsClosedAlong(triangles, edge_faces);
  for (const int c : chi) out.genus += std::max(0, (2 - c) / 2);
  return out;
}

}  // namespace acdplan::acd::internal
