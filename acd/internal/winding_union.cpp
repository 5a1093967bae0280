#include "acd/internal/winding_union.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Projection_traits_yz_3.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "acd/internal/disjoint_sets.h"
#include "acd/internal/exact_rounding.h"
#include "acd/internal/segment_crossings.h"
#include "acd/internal/separate_pinches.h"
#include "base/random.h"

namespace acdplan::acd::internal {
namespace {

using K = CGAL::Epeck;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;
using Corners = std::array<Point, 3>;

// Shells of the result below this fraction of the largest one's volume are dropped (the solid
// ACD, too, avoids cuts that leave pieces below 1e-9 of their volume).
constexpr double kSpeckFraction = 1e-9;

struct LessXyz {
  bool operator()(const Point& a, const Point& b) const {
    return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
  }
};

// What must become edges and vertices of one input triangle's refinement.
struct Constraints {
  std::vector<Segment> segments;
  std::vector<Point> points;

  void Add(const Point& a, const Point& b) {
    if (a == b) {
      points.push_back(a);
    } else {
      segments.emplace_back(a, b);
    }
  }
};

// Records where triangles t and u meet (a point, a segment, or a polygon when they are
// coplanar) in the constraints of both.
void AddIntersection(const Triangle& t, const Triangle& u, Constraints* ct, Constraints* cu) {
  const auto result = CGAL::intersection(t, u);
  if (!result) return;
  std::vector<Point> chain;  // A closed polygon's corners, or a segment's two ends.
  bool closed = true;
  if (const Point* p = boost::get<Point>(&*result)) {
    chain = {*p};
  } else if (const Segment* s = boost::get<Segment>(&*result)) {
    chain = {s->source(), s->target()};
    closed = false;
  } else if (const Triangle* r = boost::get<Triangle>(&*result)) {
    chain = {r->vertex(0), r->vertex(1), r->vertex(2)};
  } else if (const auto* polygon = boost::get<std::vector<Point>>(&*result)) {
    chain = *polygon;
  }
  for (Constraints* c : {ct, cu}) {
    if (chain.size() == 1) c->points.push_back(chain[0]);
    for (size_t k = 0; k + 1 < chain.size(); ++k) c->Add(chain[k], chain[k + 1]);
    if (closed && chain.size() >= 3) c->Add(chain.back(), chain.front());
  }
}

// Appends the constrained Delaunay triangulation of triangle `t` with `c`, computed in the
// projection `Traits` (one that keeps t non-degenerate), each triangle oriented like `t`. Every
// constraint lies in t, so the triangulation's domain is t itself.
template <class Traits>
void TriangulateIn(const Triangle& t, const Constraints& c, std::vector<Corners>* out) {
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Traits, CGAL::Default,
                                                         CGAL::Exact_intersections_tag>;
  Cdt cdt;
  for (int k = 0; k < 3; ++k) cdt.insert_constraint(t.vertex(k), t.vertex(k + 1));
  for (const Segment& s : c.segments) cdt.insert_constraint(s.source(), s.target());
  for (const Point& p : c.points) cdt.insert(p);
  const bool reversed =
      Traits().orientation_2_object()(t.vertex(0), t.vertex(1), t.vertex(2)) == CGAL::NEGATIVE;
  for (const auto face : cdt.finite_face_handles()) {
    Corners corners{face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point()};
    if (reversed) std::swap(corners[1], corners[2]);
    out->push_back(corners);
  }
}

// The refinement of `t` by its constraints, projected on the axis plane t is least inclined to.
void Refine(const Triangle& t, const Constraints& c, std::vector<Corners>* out) {
  const Vector n = CGAL::cross_product(t.vertex(1) - t.vertex(0), t.vertex(2) - t.vertex(0));
  const K::FT ax = CGAL::abs(n.x()), ay = CGAL::abs(n.y()), az = CGAL::abs(n.z());
  if (az >= ax && az >= ay) {
    TriangulateIn<CGAL::Projection_traits_xy_3<K>>(t, c, out);
  } else if (ax >= ay) {
    TriangulateIn<CGAL::Projection_traits_yz_3<K>>(t, c, out);
  } else {
    TriangulateIn<CGAL::Projection_traits_xz_3<K>>(t, c, out);
  }
}

// The winding number of `shells` just in front of `from` (a point inside a refined triangle
// of normal `normal`), counted along rays from `from` into the front side that end `reach`
// beyond every shell triangle: along `normal`, then, while a ray meets an edge or a vertex, in
// directions drawn from `rng`; empty if none of 64 is clear.
std::optional<int> FrontWinding(const std::vector<Triangle>& shells,
                                const std::vector<CGAL::Bbox_3>& boxes, double reach,
                                const Point& from, const Vector& normal, RandomEngine& rng) {
  const double scale =
      std::max({std::abs(CGAL::to_double(normal.x())), std::abs(CGAL::to_double(normal.y())),
                std::abs(CGAL::to_double(normal.z()))});
  for (int attempt = 0; attempt < 64; ++attempt) {
    Vector d = normal;
    if (attempt > 0) {
      d = d + Vector(scale * UniformReal(rng, -0.5, 0.5), scale * UniformReal(rng, -0.5, 0.5),
                     scale * UniformReal(rng, -0.5, 0.5));
      if (CGAL::sign(d * normal) != CGAL::POSITIVE) continue;
    }
    const double length =
        std::max({std::abs(CGAL::to_double(d.x())), std::abs(CGAL::to_double(d.y())),
                  std::abs(CGAL::to_double(d.z()))});
    const Point to = from + d * K::FT(reach / length);  // Beyond every shell triangle.
    const CGAL::Bbox_3 ray_box = from.bbox() + to.bbox();
    std::vector<size_t> candidates;
    for (size_t i = 0; i < shells.size(); ++i) {
      if (CGAL::do_overlap(boxes[i], ray_box)) candidates.push_back(i);
    }
    if (const std::optional<int> winding = SegmentCrossings(shells, candidates, from, to)) {
      return winding;
    }
  }
  return std::nullopt;
}

// Rounding can put a corner of a sliver triangle exactly on its opposite edge (three collinear
// corners), which cleaning would drop, opening the surface. Each such triangle (a, b, c), c
// between a and b, is removed and its neighbour (b, a, d) across ab split at c into (b, c, d)
// and (c, a, d): the same surface, still closed. Returns false if one cannot be mended (its
// neighbour is missing or itself flat); cleaning will then report it.
bool MendFlatTriangles(const std::vector<Eigen::Vector3d>& vertices,
                       std::vector<std::array<int, 3>>* triangles) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto point = [&](int v) {
    const Eigen::Vector3d& p = vertices[static_cast<size_t>(v)];
    return Epick::Point_3(p.x(), p.y(), p.z());
  };
  auto flat = [&](const std::array<int, 3>& t) {
    return CGAL::collinear(point(t[0]), point(t[1]), point(t[2])) && point(t[0]) != point(t[1]) &&
           point(t[1]) != point(t[2]) && point(t[2]) != point(t[0]);
  };
  for (int pass = 0; pass < 8; ++pass) {
    std::map<std::pair<int, int>, int> face_of;  // directed edge -> its triangle
    for (size_t f = 0; f < triangles->size(); ++f) {
      const auto& t = (*triangles)[f];
      for (size_t k = 0; k < 3; ++k) face_of[{t[k], t[(k + 1) % 3]}] = static_cast<int>(f);
    }
    std::vector<bool> removed(triangles->size(), false), touched(triangles->size(), false);
    std::vector<std::array<int, 3>> added;
    bool left = false;
    for (size_t f = 0; f < triangles->size(); ++f) {
      const std::array<int, 3> t = (*triangles)[f];
      if (!flat(t)) continue;
      // Rotate so that the corner between the other two comes last.
      size_t k = 0;
      while (k < 3 && !CGAL::collinear_are_strictly_ordered_along_line(
                          point(t[(k + 0) % 3]), point(t[(k + 2) % 3]), point(t[(k + 1) % 3]))) {
        ++k;
      }
      const int a = t[k % 3], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const auto across = face_of.find({b, a});
      if (across == face_of.end() || touched[f] || touched[static_cast<size_t>(across->second)]) {
        left = true;
        continue;
      }
      const auto& u = (*triangles)[static_cast<size_t>(across->second)];
      int d = -1;
      for (const int w : u) d = (w != a && w != b) ? w : d;
      if (flat(u)) {
        left = true;
        continue;
      }
      removed[f] = removed[static_cast<size_t>(across->second)] = true;
      touched[f] = touched[static_cast<size_t>(across->second)] = true;
      added.push_back({b, c, d});
      added.push_back({c, a, d});
    }
    if (added.empty()) return !left;
    std::vector<std::array<int, 3>> next;
    for (size_t f = 0; f < triangles->size(); ++f) {
      if (!removed[f]) next.push_back((*triangles)[f]);
    }
    next.insert(next.end(), added.begin(), added.end());
    *triangles = std::move(next);
  }
  return false;
}

// Drops the shells (edge-connected triangle sets) of `triangles` whose enclosed volume is
// below kSpeckFraction of the largest shell's: specks and bubbles where two sheets of the input
// cross almost tangentially, which no cut can use. Returns the number dropped.
int DropSpecks(const std::vector<Eigen::Vector3d>& vertices,
               std::vector<std::array<int, 3>>* triangles) {
  const int n = static_cast<int>(triangles->size());
  DisjointSets shells(n);
  std::map<std::pair<int, int>, int> first_use;  // undirected edge -> a triangle using it
  for (int f = 0; f < n; ++f) {
    const auto& t = (*triangles)[static_cast<size_t>(f)];
    for (size_t k = 0; k < 3; ++k) {
      const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
      const auto [it, inserted] = first_use.emplace(edge, f);
      if (!inserted) shells.Unite(it->second, f);
    }
  }
  std::map<int, double> volume;  // shell (its lowest triangle) -> 6 x its signed volume
  for (int f = 0; f < n; ++f) {
    const auto& t = (*triangles)[static_cast<size_t>(f)];
    volume[shells.Find(f)] += vertices[static_cast<size_t>(t[0])].dot(
        vertices[static_cast<size_t>(t[1])].cross(vertices[static_cast<size_t>(t[2])]));
  }
  double largest = 0;
  for (const auto& [shell, v] : volume) largest = std::max(largest, std::abs(v));
  std::vector<std::array<int, 3>> kept;
  int dropped = 0;
  for (const auto& [shell, v] : volume) dropped += std::abs(v) < kSpeckFraction * largest;
  if (dropped == 0) return 0;
  for (int f = 0; f < n; ++f) {
    if (!(std::abs(volume[shells.Find(f)]) < kSpeckFraction * largest)) {
      kept.push_back((*triangles)[static_cast<size_t>(f)]);
    }
  }
  *triangles = std::move(kept);
  return dropped;
}

// Renumbers `triangles` (over `count` vertices) to the vertices they use, kept in their order;
// returns the old index of each new vertex.
std::vector<size_t> KeepUsedVertices(size_t count, std::vector<std::array<int, 3>>* triangles) {
  std::vector<int> renumber(count, -1);
  for (const auto& t : *triangles) {
    for (const int v : t) renumber[static_cast<size_t>(v)] = 0;
  }
  std::vector<size_t> used;
  for (size_t v = 0; v < count; ++v) {
    if (renumber[v] < 0) continue;
    renumber[v] = static_cast<int>(used.size());
    used.push_back(v);
  }
  for (auto& t : *triangles) {
    for (int& v : t) v = renumber[static_cast<size_t>(v)];
  }
  return used;
}

// Rotates t so that its lowest vertex comes first (the orientation is kept).
std::array<int, 3> LowestFirst(const std::array<int, 3>& t) {
  const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  return {t[static_cast<size_t>(k)], t[static_cast<size_t>((k + 1) % 3)],
          t[static_cast<size_t>((k + 2) % 3)]};
}

}  // namespace

std::optional<WindingUnion> UniteByWinding(const TriangleMesh& mesh, const std::vector<int>& faces,
                                           const std::vector<std::pair<int, int>>& crossings) {
  // 1. The input triangles, exact, and their refinements.
  std::vector<int> slot(static_cast<size_t>(mesh.triangles.rows()), -1);
  std::vector<Triangle> shells;
  std::vector<CGAL::Bbox_3> boxes;
  CGAL::Bbox_3 all;
  for (const int f : faces) {
    slot[static_cast<size_t>(f)] = static_cast<int>(shells.size());
    Corners corners;
    for (int k = 0; k < 3; ++k) {
      const auto row = mesh.vertices.row(mesh.triangles(f, k));
      corners[static_cast<size_t>(k)] = Point(row(0), row(1), row(2));
    }
    shells.emplace_back(corners[0], corners[1], corners[2]);
    boxes.push_back(shells.back().bbox());
    all += boxes.back();
  }
  std::vector<Constraints> constraints(shells.size());
  for (const auto& [f, g] : crossings) {
    const int i = slot[static_cast<size_t>(f)], j = slot[static_cast<size_t>(g)];
    if (i < 0 || j < 0) continue;
    AddIntersection(shells[static_cast<size_t>(i)], shells[static_cast<size_t>(j)],
                    &constraints[static_cast<size_t>(i)], &constraints[static_cast<size_t>(j)]);
  }
  std::vector<Corners> refined;
  for (size_t i = 0; i < shells.size(); ++i) {
    const Constraints& c = constraints[i];
    if (c.segments.empty() && c.points.empty()) {
      refined.push_back({shells[i][0], shells[i][1], shells[i][2]});
    } else {
      Refine(shells[i], c, &refined);
    }
  }

  // Vertices numbered in exact lexicographic order.
  using Index = std::map<Point, int, LessXyz>;
  Index index;
  std::vector<std::array<Index::const_iterator, 3>> corner_at;  // each corner's entry, found once
  corner_at.reserve(refined.size());
  for (const Corners& t : refined) {
    corner_at.push_back(
        {index.emplace(t[0], 0).first, index.emplace(t[1], 0).first, index.emplace(t[2], 0).first});
  }
  std::vector<Point> points;
  points.reserve(index.size());
  for (auto& [p, id] : index) {
    id = static_cast<int>(points.size());
    points.push_back(p);
  }

  // 2. Identical triangles grouped, with their multiplicity, oriented so that it is > 0.
  std::map<std::array<int, 3>, int> multiplicity;
  for (const auto& at : corner_at) {
    const std::array<int, 3> r = LowestFirst({at[0]->second, at[1]->second, at[2]->second});
    multiplicity[{r[0], std::min(r[1], r[2]), std::max(r[1], r[2])}] += r[1] < r[2] ? 1 : -1;
  }
  std::vector<std::array<int, 3>> groups;
  std::vector<int> times;
  for (const auto& [key, m] : multiplicity) {
    if (m == 0) continue;  // Opposite copies cancel: w is the same on both sides.
    groups.push_back(m > 0 ? key : std::array<int, 3>{key[0], key[2], key[1]});
    times.push_back(std::abs(m));
  }
  const int count = static_cast<int>(groups.size());

  // 3. Patches: groups joined across edges only they use, consistently.
  struct EdgeUse {
    int lo, hi, group;
    bool forward;
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * groups.size());
  for (int g = 0; g < count; ++g) {
    const auto& t = groups[static_cast<size_t>(g)];
    for (size_t k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), g, a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) {
    return std::tie(a.lo, a.hi, a.group) < std::tie(b.lo, b.hi, b.group);
  });
  DisjointSets patches(count);
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    if (j - i == 2 && uses[i].forward != uses[i + 1].forward &&
        times[static_cast<size_t>(uses[i].group)] ==
            times[static_cast<size_t>(uses[i + 1].group)]) {
      patches.Unite(uses[i].group, uses[i + 1].group);
    }
    i = j;
  }

  // The winding number in front of each patch, from its lowest group.
  const double reach = 2.0 * std::sqrt(CGAL::square(all.xmax() - all.xmin()) +
                                       CGAL::square(all.ymax() - all.ymin()) +
                                       CGAL::square(all.zmax() - all.zmin())) +
                       1.0;
  // First along the axis each patch's normal leans to most: such rays have thin boxes, and the
  // shell triangles whose boxes they meet are found for all of them at once.
  std::vector<Point> from(static_cast<size_t>(count));
  std::vector<Vector> normal(static_cast<size_t>(count));
  std::vector<std::optional<Point>> axis_end(static_cast<size_t>(count));
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, size_t>;
  std::vector<Box> ray_boxes, shell_boxes;
  for (int g = 0; g < count; ++g) {
    if (patches.Find(g) != g) continue;
    const auto& t = groups[static_cast<size_t>(g)];
    const Point& a = points[static_cast<size_t>(t[0])];
    const Point& b = points[static_cast<size_t>(t[1])];
    const Point& c = points[static_cast<size_t>(t[2])];
    const size_t i = static_cast<size_t>(g);
    from[i] = CGAL::centroid(a, b, c);
    normal[i] = CGAL::cross_product(b - a, c - a);
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (std::abs(CGAL::to_double(normal[i][k])) > std::abs(CGAL::to_double(normal[i][axis]))) {
        axis = k;
      }
    }
    const CGAL::Sign sign = CGAL::sign(normal[i][axis]);
    if (sign == CGAL::ZERO) continue;
    std::array<double, 3> step = {0, 0, 0};
    step[static_cast<size_t>(axis)] = sign == CGAL::POSITIVE ? reach : -reach;
    axis_end[i] = from[i] + Vector(step[0], step[1], step[2]);
    ray_boxes.emplace_back(from[i].bbox() + axis_end[i]->bbox(), i);
  }
  for (size_t i = 0; i < shells.size(); ++i) shell_boxes.emplace_back(boxes[i], i);
  std::vector<std::vector<size_t>> met(static_cast<size_t>(count));
  CGAL::box_intersection_d(
      ray_boxes.begin(), ray_boxes.end(), shell_boxes.begin(), shell_boxes.end(),
      [&](const Box& ray, const Box& shell) { met[ray.info()].push_back(shell.info()); });
  RandomEngine rng(1);  // Only for rays that must be cast again.
  std::vector<std::optional<int>> front(static_cast<size_t>(count));
  for (int g = 0; g < count; ++g) {
    if (patches.Find(g) != g) continue;
    const size_t i = static_cast<size_t>(g);
    if (axis_end[i]) front[i] = SegmentCrossings(shells, met[i], from[i], *axis_end[i]);
    if (!front[i]) front[i] = FrontWinding(shells, boxes, reach, from[i], normal[i], rng);
    if (!front[i]) return std::nullopt;
  }

  // 4. The groups between w <= 0 and w > 0, facing w <= 0.
  std::vector<std::array<int, 3>> kept;
  for (int g = 0; g < count; ++g) {
    const int in_front = *front[static_cast<size_t>(patches.Find(g))];
    const int behind = in_front + times[static_cast<size_t>(g)];
    if ((in_front > 0) == (behind > 0)) continue;
    std::array<int, 3> t = groups[static_cast<size_t>(g)];
    if (in_front > 0) std::swap(t[1], t[2]);
    kept.push_back(t);
  }
  if (kept.empty()) return std::nullopt;

  // Only the vertices used, in the same (lexicographic) order.
  std::vector<Eigen::Vector3d> vertices;
  for (const size_t v : KeepUsedVertices(points.size(), &kept)) {
    vertices.push_back(RoundToDouble(points[v]));  // See RoundToDouble() on why.
  }
  std::vector<std::array<int, 3>> sorted = std::move(kept);
  WindingUnion out;
  MendFlatTriangles(vertices, &sorted);
  out.pinches =
      SeparatePinches(&vertices, &sorted).separated;  // PrepareMesh() checks what is left.
  out.specks = DropSpecks(vertices, &sorted);
  if (out.specks > 0) {  // Their vertices go too (the order of the others is kept).
    std::vector<Eigen::Vector3d> compact;
    for (const size_t v : KeepUsedVertices(vertices.size(), &sorted))
      compact.push_back(vertices[v]);
    vertices = std::move(compact);
  }
  for (auto& t : sorted) t = LowestFirst(t);
  std::sort(sorted.begin(), sorted.end());
  std::vector<Eigen::Vector3i> triangles;
  triangles.reserve(sorted.size());
  for (const auto& t : sorted) triangles.emplace_back(t[0], t[1], t[2]);
  out.mesh = MakeTriangleMesh(vertices, triangles);
  return out;
}

}  // namespace acdplan::acd::internal
