#include "acd/prepare_polygon.h"

#include <CGAL/Arr_non_caching_segment_traits_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Surface_sweep_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "acd/internal/box_sweep.h"
#include "acd/internal/disjoint_sets.h"
#include "acd/internal/ring_name.h"
#include "acd/internal/text_parsing.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

using internal::RingName;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_2;
using CgalSegment = Kernel::Segment_2;

CgalPoint ToCgal(const Point2d& p) { return CgalPoint(p.x(), p.y()); }

// A ring during cleaning: positions plus, for each, its index in the ring as given to
// PreparePolygon(), so that messages can name the vertices the user wrote.
struct IndexedRing {
  std::vector<CgalPoint> points;
  std::vector<int> input_index;
  size_t size() const { return points.size(); }
};

[[noreturn]] void Fail(const std::string& where, const std::string& message) {
  throw InputError(where + ": " + message);
}

// Drops consecutive duplicates (the repeated closing vertex is one), collinear vertices and
// zero-width spikes until no vertex is collinear with its two neighbours. A work list over a
// circular doubly linked list makes this O(n): removing a vertex re-examines only its two
// neighbours. Every test is CGAL's exact orientation predicate.
IndexedRing CleanRing(const Ring2d& raw) {
  const int n = static_cast<int>(raw.size());
  std::vector<CgalPoint> points;
  points.reserve(raw.size());
  for (const Point2d& p : raw) points.push_back(ToCgal(p));
  std::vector<int> prev(n), next(n);
  std::vector<char> alive(n, 1);
  for (int i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::vector<int> work(n);
  for (int i = 0; i < n; ++i) work[i] = n - 1 - i;  // Pop in input order.
  int remaining = n;
  while (!work.empty() && remaining >= 3) {
    const int i = work.back();
    work.pop_back();
    if (!alive[i]) continue;
    const int a = prev[i];
    const int b = next[i];
    int victim = -1;
    if (points[i] == points[b]) {
      victim = std::max(i, b);  // Of duplicates keep the first written (the closing vertex goes).
    } else if (points[i] == points[a]) {
      victim = std::max(i, a);
    } else if (CGAL::orientation(points[a], points[i], points[b]) == CGAL::COLLINEAR) {
      victim = i;  // On a straight run, or the tip of a zero-width spike.
    }
    if (victim >= 0) {
      const int before = prev[victim];
      const int after = next[victim];
      alive[victim] = 0;
      next[before] = after;
      prev[after] = before;
      --remaining;
      work.push_back(after);
      work.push_back(before);
      if (victim != i) work.push_back(i);
    }
  }
  IndexedRing ring;
  int first = 0;
  while (first < n && !alive[first]) ++first;
  if (first == n) return ring;
  if (remaining < 3) {
    // Keep the distinct positions only, for the message.
    int i = first;
    do {
      if (ring.points.empty() || ring.points.back() != points[i]) {
        ring.points.push_back(points[i]);
        ring.input_index.push_back(i);
      }
      i = next[i];
    } while (i != first);
    return ring;
  }
  int i = first;
  do {
    ring.points.push_back(points[i]);
    ring.input_index.push_back(i);
    i = next[i];
  } while (i != first);
  return ring;
}

// Orientation of a ring without collinear consecutive vertices, exact: the turn at the
// lexicographically smallest vertex (a vertex of the convex hull) is the ring's orientation
// when the ring is simple. (Non-simple rings are rejected later anyway.)
CGAL::Orientation RingOrientation(const IndexedRing& ring) {
  const size_t n = ring.size();
  size_t lowest = 0;
  for (size_t i = 1; i < n; ++i) {
    if (ring.points[i] < ring.points[lowest]) lowest = i;
  }
  return CGAL::orientation(ring.points[(lowest + n - 1) % n], ring.points[lowest],
                           ring.points[(lowest + 1) % n]);
}

void Reverse(IndexedRing& ring) {
  std::reverse(ring.points.begin(), ring.points.end());
  std::reverse(ring.input_index.begin(), ring.input_index.end());
}

double TwiceArea(const IndexedRing& ring) {
  Ring2d plain;
  plain.reserve(ring.size());
  for (const CgalPoint& p : ring.points) plain.emplace_back(p.x(), p.y());
  return 2.0 * SignedArea(plain);
}

// An edge of ring `ring` from vertex `index` to vertex `index + 1` (cyclically).
struct EdgeRef {
  int ring;
  int index;
};

// The first intersection among `edges` of `rings`, in (ring, index) order of the pair, between
// edges that are not neighbours on the same ring. `only_between_rings` skips pairs of one ring.
struct Hit {
  EdgeRef a;
  EdgeRef b;
  CgalPoint at;
  bool overlap;
};

// True when intersecting segments `a` and `b` share exactly one point and that point is an end
// point of one of them: a touching, not a crossing or an overlap. Exact predicates only.
bool IsTouching(const CgalSegment& a, const CgalSegment& b) {
  const bool collinear = CGAL::collinear(a.source(), a.target(), b.source()) &&
                         CGAL::collinear(a.source(), a.target(), b.target());
  if (collinear) {
    // Collinear segments touch when they share only an end point.
    auto only_end = [](const CgalSegment& s, const CgalSegment& t) {
      return (s.target() == t.source() && !t.has_on(s.source()) && !s.has_on(t.target())) ||
             (s.source() == t.target() && !t.has_on(s.target()) && !s.has_on(t.source())) ||
             (s.source() == t.source() && !t.has_on(s.target()) && !s.has_on(t.target())) ||
             (s.target() == t.target() && !t.has_on(s.source()) && !s.has_on(t.source()));
    };
    return only_end(a, b);
  }
  return b.has_on(a.source()) || b.has_on(a.target()) || a.has_on(b.source()) ||
         a.has_on(b.target());
}

// Sort-by-x sweep with bounding boxes and exact do_intersect tests: O(n log n + k) for k
// pairs whose x-ranges overlap. Only called once a sweep (below) has found that something
// intersects, to name the edges.
// `only_with_outer` skips pairs of which neither edge is on ring 0. `allow_touching` skips pairs
// that meet in one point that is an end point of one of them (a vertex touching an edge or a
// vertex), so that only crossings and overlaps are found.
std::optional<Hit> FindIntersection(const std::vector<IndexedRing>& rings,
                                    const std::vector<EdgeRef>& edges, bool only_between_rings,
                                    bool allow_touching = false, bool only_with_outer = false) {
  struct Box {
    double xmin, xmax, ymin, ymax;
  };
  auto segment = [&](const EdgeRef& e) {
    const IndexedRing& r = rings[static_cast<size_t>(e.ring)];
    return CgalSegment(r.points[static_cast<size_t>(e.index)],
                       r.points[(static_cast<size_t>(e.index) + 1) % r.size()]);
  };
  std::vector<Box> boxes(edges.size());
  for (size_t i = 0; i < edges.size(); ++i) {
    const CgalSegment s = segment(edges[i]);
    boxes[i] = {std::min(s.source().x(), s.target().x()), std::max(s.source().x(), s.target().x()),
                std::min(s.source().y(), s.target().y()), std::max(s.source().y(), s.target().y())};
  }
  std::vector<size_t> order(edges.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](size_t l, size_t r) { return boxes[l].xmin < boxes[r].xmin; });
  auto key = [&](const EdgeRef& a, const EdgeRef& b) {
    return std::make_tuple(a.ring, a.index, b.ring, b.index);
  };
  std::optional<Hit> best;
  for (size_t oi = 0; oi < order.size(); ++oi) {
    const size_t i = order[oi];
    for (size_t oj = oi + 1; oj < order.size() && boxes[order[oj]].xmin <= boxes[i].xmax; ++oj) {
      const size_t j = order[oj];
      if (boxes[j].ymin > boxes[i].ymax || boxes[i].ymin > boxes[j].ymax) continue;
      EdgeRef a = edges[i];
      EdgeRef b = edges[j];
      if (std::make_pair(b.ring, b.index) < std::make_pair(a.ring, a.index)) std::swap(a, b);
      if (only_with_outer && a.ring != 0 && b.ring != 0) continue;
      if (a.ring == b.ring) {
        if (only_between_rings) continue;
        const int n = static_cast<int>(rings[static_cast<size_t>(a.ring)].size());
        // Neighbours share a vertex; cleaning guarantees they meet nowhere else.
        if (b.index == a.index + 1 || (a.index == 0 && b.index == n - 1)) continue;
      }
      if (best && key(a, b) >= key(best->a, best->b)) continue;
      const CgalSegment sa = segment(a);
      const CgalSegment sb = segment(b);
      if (!CGAL::do_intersect(sa, sb)) continue;
      if (allow_touching && IsTouching(sa, sb)) continue;
      Hit hit{a, b, sa.source(), false};
      const auto where = CGAL::intersection(sa, sb);
      if (where) {
        if (const CgalPoint* p = boost::get<CgalPoint>(&*where)) {
          hit.at = *p;
        } else if (const CgalSegment* s = boost::get<CgalSegment>(&*where)) {
          hit.at = s->source();
          hit.overlap = true;
        }
      }
      best = hit;
    }
  }
  return best;
}

std::string EdgeName(const std::vector<IndexedRing>& rings, const EdgeRef& e) {
  const IndexedRing& r = rings[static_cast<size_t>(e.ring)];
  return "(" + std::to_string(r.input_index[static_cast<size_t>(e.index)]) + "," +
         std::to_string(r.input_index[(static_cast<size_t>(e.index) + 1) % r.size()]) + ")";
}

std::string Describe(const Hit& hit) {
  return (hit.overlap ? " overlap from " : " intersect at ") +
         internal::FormatPoint(Point2d(hit.at.x(), hit.at.y()));
}

std::vector<EdgeRef> EdgesOf(const std::vector<IndexedRing>& rings, int first_ring, int last_ring) {
  std::vector<EdgeRef> edges;
  for (int r = first_ring; r <= last_ring; ++r) {
    const int n = static_cast<int>(rings[static_cast<size_t>(r)].size());
    for (int i = 0; i < n; ++i) edges.push_back({r, i});
  }
  return edges;
}

// True when no two edges of all rings meet, except neighbouring edges of one ring at their
// shared vertex. O(n log n): CGAL's surface sweep (Bentley-Ottmann) stopping at the first
// interior intersection, plus a sort for vertices that coincide (which the sweep does not
// report, since they meet at segment end points). The sweep constructs intersection points and
// orders them against the segments, so it runs on Epeck (exact constructions; the input doubles
// convert exactly): with Epick's rounded constructions it misses crossings, e.g. it finds none
// between (1, 0)-(1, 2) and (5, 4)-(0, 0), whose crossing (1, 0.8) is not a double.
// A polygon of few edges (a building footprint, a grid cell's obstacle) has every pair tested
// instead, with exact predicates alone (no point is constructed): the sweep's set-up costs more
// than the pairs.
bool RingsAreDisjointAndSimple(const std::vector<IndexedRing>& rings) {
  using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
  std::vector<CgalPoint> vertices;
  for (const IndexedRing& ring : rings) {
    vertices.insert(vertices.end(), ring.points.begin(), ring.points.end());
  }
  std::sort(vertices.begin(), vertices.end());
  if (std::adjacent_find(vertices.begin(), vertices.end()) != vertices.end()) return false;
  constexpr size_t kFewEdges = 24;
  if (vertices.size() <= kFewEdges) {
    struct Edge {
      size_t ring, i;
      CgalPoint a, b;
    };
    std::vector<Edge> edges;
    for (size_t r = 0; r < rings.size(); ++r) {
      const std::vector<CgalPoint>& points = rings[r].points;
      for (size_t i = 0; i < points.size(); ++i) {
        edges.push_back({r, i, points[i], points[(i + 1) % points.size()]});
      }
    }
    for (size_t e = 0; e < edges.size(); ++e) {
      for (size_t f = e + 1; f < edges.size(); ++f) {
        const Edge& x = edges[e];
        const Edge& y = edges[f];
        const size_t n = rings[x.ring].size();
        const bool x_then_y = x.ring == y.ring && (x.i + 1) % n == y.i;
        const bool y_then_x = x.ring == y.ring && (y.i + 1) % n == x.i;
        if (x_then_y || y_then_x) {
          // Neighbours share one vertex (no vertex repeats): they meet beyond it only when
          // the three are collinear and the outer two lie on the same side of it.
          const CgalPoint& shared = x_then_y ? x.b : x.a;
          const CgalPoint& p = x_then_y ? x.a : x.b;
          const CgalPoint& q = x_then_y ? y.b : y.a;
          if (CGAL::orientation(p, shared, q) == CGAL::COLLINEAR &&
              CGAL::compare_xy(p, shared) == CGAL::compare_xy(q, shared)) {
            return false;
          }
        } else if (CGAL::do_intersect(Kernel::Segment_2(x.a, x.b), Kernel::Segment_2(y.a, y.b))) {
          return false;
        }
      }
    }
    return true;
  }
  std::vector<Exact::Segment_2> segments;
  for (const IndexedRing& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const CgalPoint& a = ring.points[i];
      const CgalPoint& b = ring.points[(i + 1) % ring.size()];
      segments.emplace_back(Exact::Point_2(a.x(), a.y()), Exact::Point_2(b.x(), b.y()));
    }
  }
  CGAL::Arr_non_caching_segment_traits_2<Exact> traits;
  return !CGAL::do_curves_intersect(segments.begin(), segments.end(), traits);
}

// ---- Rings that touch at points (the OGC-valid case) ----------------------------------------

// Sign of the ring's signed area, exact (the sum of cross products in rationals, after a
// floating-point filter). For a ring that touches itself it is the orientation of the part that
// encloses most area, which is the orientation the ring is meant to have.
CGAL::Sign ExactAreaSign(const IndexedRing& ring) {
  const size_t n = ring.size();
  double sum = 0.0;
  double magnitude = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const CgalPoint& a = ring.points[i];
    const CgalPoint& b = ring.points[(i + 1) % n];
    sum += a.x() * b.y() - b.x() * a.y();
    magnitude += std::abs(a.x() * b.y()) + std::abs(b.x() * a.y());
  }
  // Each term and each addition errs by at most eps relative to `magnitude`.
  if (std::abs(sum) > 4.0 * static_cast<double>(n + 2) * 1.2e-16 * magnitude) {
    return sum > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
  }
  CGAL::Exact_rational exact = 0;
  for (size_t i = 0; i < n; ++i) {
    const CgalPoint& a = ring.points[i];
    const CgalPoint& b = ring.points[(i + 1) % n];
    exact += CGAL::Exact_rational(a.x()) * CGAL::Exact_rational(b.y()) -
             CGAL::Exact_rational(b.x()) * CGAL::Exact_rational(a.y());
  }
  return CGAL::sign(exact);
}

struct TouchFaceInfo {
  int winding = INT_MIN;  // Winding number of the rings around the triangle; INT_MIN: not yet.
  int component = -1;     // Connected part of the interior (triangles with winding 1).
  int piece = -1;         // Output polygon.
};
using TouchVb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using TouchFb =
    CGAL::Triangulation_face_base_with_info_2<TouchFaceInfo, Kernel,
                                              CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using TouchTds = CGAL::Triangulation_data_structure_2<TouchVb, TouchFb>;
// Rings only touch here (crossings and overlaps are rejected before), so a constraint meets
// another only at an input vertex: no constructed point, and Epick's predicates are exact.
using TouchCdt = CGAL::Constrained_triangulation_plus_2<CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, TouchTds, CGAL::No_constraint_intersection_requiring_constructions_tag>>;
using FaceHandle = TouchCdt::Face_handle;
using VertexHandle = TouchCdt::Vertex_handle;

uint64_t EdgeKey(int a, int b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

// Breadth first over the triangles from `start`: for each triangle f reached and each of its
// edges i, `enter(f, i)` decides whether the walk goes on into f->neighbor(i), marking it so
// that it is entered once. `queue`: storage, empty on return.
template <typename Enter>
void WalkTriangles(const FaceHandle& start, Enter enter, std::deque<FaceHandle>* queue) {
  queue->push_back(start);
  while (!queue->empty()) {
    const FaceHandle f = queue->front();
    queue->pop_front();
    for (int i = 0; i < 3; ++i) {
      if (enter(f, i)) queue->push_back(f->neighbor(i));
    }
  }
}

// The first vertex of ring `r` that is not on `other` (a ring's points), with its bounded side;
// ON_BOUNDARY when all are on it.
CGAL::Bounded_side SideOfRing(const IndexedRing& ring, const std::vector<CgalPoint>& other,
                              size_t* vertex) {
  for (size_t i = 0; i < ring.size(); ++i) {
    const CGAL::Bounded_side side =
        CGAL::bounded_side_2(other.begin(), other.end(), ring.points[i], Kernel());
    if (side != CGAL::ON_BOUNDARY) {
      *vertex = i;
      return side;
    }
  }
  return CGAL::ON_BOUNDARY;
}

// Disjoint (or only touching) holes are nested when one's vertex off the other's ring lies
// inside the other. Only holes whose bounding boxes overlap are tested (internal::
// ForEachSelfOverlap()), and of those only a box inside the other. Where several pairs nest, the
// first in (inner, outer) hole order is named.
void RejectNestedHoles(const std::vector<IndexedRing>& rings, const std::string& where) {
  std::vector<internal::IdBox> boxes;
  for (size_t r = 1; r < rings.size(); ++r) {
    CGAL::Bbox_2 b;
    for (const CgalPoint& p : rings[r].points) b += p.bbox();
    boxes.push_back({{b.xmin(), b.ymin()}, {b.xmax(), b.ymax()}, static_cast<int>(r)});
  }
  auto box_of = [&](size_t r) -> const internal::IdBox& { return boxes[r - 1]; };
  std::pair<size_t, size_t> nested{rings.size(), rings.size()};  // (inner, outer)
  auto test = [&](size_t inner, size_t outer) {
    if (!internal::BoxWithin(box_of(inner), box_of(outer)) ||
        std::make_pair(inner, outer) > nested) {
      return;
    }
    size_t vertex = 0;
    if (SideOfRing(rings[inner], rings[outer].points, &vertex) == CGAL::ON_BOUNDED_SIDE) {
      nested = {inner, outer};
    }
  };
  internal::ForEachSelfOverlap(boxes, [&](int a, int b) {
    test(static_cast<size_t>(a), static_cast<size_t>(b));
    test(static_cast<size_t>(b), static_cast<size_t>(a));
  });
  if (nested.first < rings.size()) {
    Fail(where, RingName(nested.first) + " lies inside " + RingName(nested.second) +
                    " (holes must not be nested)");
  }
}

// PreparePolygons() once the fast test found rings that meet: validates the touchings and
// splits the interior into polygons whose rings are simple and disjoint (see the header).
std::vector<Polygon2d> PrepareTouching(std::vector<IndexedRing> rings, const std::string& where) {
  const int last = static_cast<int>(rings.size()) - 1;
  // Crossings and overlaps, in the order and with the messages of the strict checks.
  for (int r = 0; r <= last; ++r) {
    if (const auto hit = FindIntersection(rings, EdgesOf(rings, r, r), false, true)) {
      Fail(where, RingName(r) + " is not simple: edges " + EdgeName(rings, hit->a) + " and " +
                      EdgeName(rings, hit->b) + Describe(*hit));
    }
  }
  // All holes against the outer ring in one sweep (pairs of two holes are skipped here).
  if (last >= 1) {
    if (const auto hit = FindIntersection(rings, EdgesOf(rings, 0, last), true, true, true)) {
      const int h = hit->b.ring;
      Fail(where, RingName(h) +
                      " touches or crosses the outer ring (a hole must lie strictly "
                      "inside): outer edge " +
                      EdgeName(rings, hit->a) + " and hole edge " + EdgeName(rings, hit->b) +
                      Describe(*hit));
    }
  }
  // A ring touching itself may enclose area on the wrong side of the lowest vertex's turn:
  // orient by the exact sign of the area instead.
  for (int r = 0; r <= last; ++r) {
    const CGAL::Sign wanted = r == 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
    if (ExactAreaSign(rings[static_cast<size_t>(r)]) != wanted)
      Reverse(rings[static_cast<size_t>(r)]);
  }
  for (int h = 1; h <= last; ++h) {
    size_t i = 0;
    if (SideOfRing(rings[static_cast<size_t>(h)], rings[0].points, &i) == CGAL::ON_UNBOUNDED_SIDE) {
      const CgalPoint& p = rings[static_cast<size_t>(h)].points[i];
      Fail(where, RingName(h) + " is not inside the outer ring: its vertex " +
                      std::to_string(rings[static_cast<size_t>(h)].input_index[i]) + " " +
                      internal::FormatPoint(Point2d(p.x(), p.y())) + " is outside");
    }
  }
  if (const auto hit = FindIntersection(rings, EdgesOf(rings, 1, last), true, true)) {
    Fail(where, RingName(hit->a.ring) + " and " + RingName(hit->b.ring) +
                    " touch or overlap (holes must be disjoint): edges " + EdgeName(rings, hit->a) +
                    " and " + EdgeName(rings, hit->b) + Describe(*hit));
  }
  RejectNestedHoles(rings, where);

  // Constrained triangulation of all ring edges. Vertex info: index into `owners`.
  TouchCdt cdt;
  std::vector<std::vector<VertexHandle>> handles(rings.size());
  std::vector<std::vector<int>> owners;  // Per triangulation vertex: the rings through it.
  VertexHandle hint;
  for (size_t r = 0; r < rings.size(); ++r) {
    for (const CgalPoint& p : rings[r].points) {
      VertexHandle v = cdt.insert(p, hint == VertexHandle() ? FaceHandle() : hint->face());
      handles[r].push_back(v);
      hint = v;
    }
  }
  // Number the vertices after insertion (info defaults are unspecified).
  int vertex_count = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info() = vertex_count++;
  }
  owners.assign(static_cast<size_t>(vertex_count), {});
  for (size_t r = 0; r < rings.size(); ++r) {
    for (const VertexHandle& v : handles[r]) {
      std::vector<int>& o = owners[static_cast<size_t>(v->info())];
      if (o.empty() || o.back() != static_cast<int>(r)) o.push_back(static_cast<int>(r));
    }
  }
  // Net number of ring edges running a -> b minus b -> a, per triangulation edge, and the
  // ring of each (for the hole-connectivity rule).
  std::unordered_map<uint64_t, int> net;
  struct SubEdge {
    VertexHandle a, b;
    int ring;
  };
  std::vector<SubEdge> sub_edges;
  for (size_t r = 0; r < rings.size(); ++r) {
    const size_t n = handles[r].size();
    for (size_t i = 0; i < n; ++i) {
      const auto id = cdt.insert_constraint(handles[r][i], handles[r][(i + 1) % n]);
      VertexHandle previous;
      for (auto v = cdt.vertices_in_constraint_begin(id); v != cdt.vertices_in_constraint_end(id);
           ++v) {
        if (previous != VertexHandle()) {
          ++net[EdgeKey(previous->info(), (*v)->info())];
          --net[EdgeKey((*v)->info(), previous->info())];
          sub_edges.push_back({previous, *v, static_cast<int>(r)});
        }
        previous = *v;
      }
    }
  }
  auto net_of = [&](const VertexHandle& a, const VertexHandle& b) {
    const auto it = net.find(EdgeKey(a->info(), b->info()));
    return it == net.end() ? 0 : it->second;
  };

  // Winding numbers by a walk over the triangles: crossing edge a -> b (the triangle on its
  // left) to the right decreases the winding by net(a -> b).
  std::deque<FaceHandle> queue;
  cdt.infinite_face()->info().winding = 0;
  WalkTriangles(
      cdt.infinite_face(),
      [&](const FaceHandle& f, int i) {
        const FaceHandle g = f->neighbor(i);
        if (g->info().winding != INT_MIN) return false;
        const VertexHandle a = f->vertex(TouchCdt::ccw(i));
        const VertexHandle b = f->vertex(TouchCdt::cw(i));
        const bool infinite = cdt.is_infinite(a) || cdt.is_infinite(b);
        g->info().winding = f->info().winding - (infinite ? 0 : net_of(a, b));
        return true;
      },
      &queue);
  auto point_of = [](const VertexHandle& v) { return Point2d(v->point().x(), v->point().y()); };
  auto rings_at = [&](const VertexHandle& v) {
    const std::vector<int>& o = owners[static_cast<size_t>(v->info())];
    std::string names;
    for (size_t k = 0; k < o.size(); ++k) {
      names += (k == 0 ? "" : k + 1 == o.size() ? " and " : ", ") + RingName(o[k]);
    }
    return names;
  };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int w = f->info().winding;
    if (w == 0 || w == 1) continue;
    // Rings that only touch give windings 0 and 1; anything else is a crossing at a shared
    // vertex (the strict crossing tests above found no other). Name the vertex where rings meet.
    for (int i = 0; i < 3; ++i) {
      const VertexHandle v = f->vertex(i);
      if (owners[static_cast<size_t>(v->info())].size() > 1 ||
          cdt.are_there_incident_constraints(v)) {
        int constraints = 0;
        auto e = cdt.incident_edges(v);
        const auto done = e;
        do {
          if (!cdt.is_infinite(e) && cdt.is_constrained(*e)) ++constraints;
        } while (++e != done);
        if (constraints < 4) continue;
        const std::vector<int>& o = owners[static_cast<size_t>(v->info())];
        Fail(where, (o.size() == 1 ? RingName(o[0]) + " crosses itself" : rings_at(v) + " cross") +
                        " at the shared vertex " + internal::FormatPoint(point_of(v)) +
                        " (rings may touch at points but not cross)");
      }
    }
    Fail(where, "rings cross or overlap near " + internal::FormatPoint(point_of(f->vertex(0))) +
                    " (winding number " + std::to_string(w) + ")");
  }

  // Connected parts of the interior: triangles of winding 1 joined across unconstrained edges.
  int components = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().winding != 1 || f->info().component >= 0) continue;
    f->info().component = components;
    WalkTriangles(
        f,
        [&](const FaceHandle& g, int i) {
          const FaceHandle h = g->neighbor(i);
          if (h->info().winding != 1 || h->info().component >= 0 || cdt.is_constrained({g, i})) {
            return false;
          }
          h->info().component = components;
          return true;
        },
        &queue);
    ++components;
  }
  // A hole bordering two parts closes a chain of touching rings across the interior.
  std::vector<int> hole_component(rings.size(), -1);
  for (const SubEdge& e : sub_edges) {
    if (e.ring == 0) continue;
    FaceHandle f;
    int i = 0;
    cdt.is_edge(e.a, e.b, f, i);
    if (f->vertex(TouchCdt::ccw(i)) != e.a) f = f->neighbor(i);  // The triangle left of a -> b.
    const int c = f->info().component;
    int& seen = hole_component[static_cast<size_t>(e.ring)];
    if (seen >= 0 && c != seen) {
      Fail(where, RingName(e.ring) +
                      " disconnects the interior: with the rings it touches it closes a chain "
                      "around part of the polygon (the interior must stay connected), e.g. "
                      "at " +
                      internal::FormatPoint(point_of(e.a)));
    }
    seen = c;
  }

  // Pieces. A part without pinch vertices (where its triangles form one fan sector) is one
  // polygon. A part with pinches is grown triangle by triangle, adding a triangle only while
  // every vertex keeps one fan sector of the piece (a 2-manifold: simple, disjoint rings).
  // The fan sectors around v of the triangles with the same `label` (>= 0): runs of them
  // counter-clockwise, ended by a triangle of another label or a constrained edge; one call of
  // `sector_end(label)` per run.
  auto for_each_sector_end = [&](const VertexHandle& v, auto label, auto sector_end) {
    auto f = cdt.incident_faces(v);
    const auto done = f;
    do {
      const int l = label(f);
      auto next = f;
      ++next;
      if (l >= 0 && (label(next) != l || cdt.is_constrained({f, f->index(next)}))) sector_end(l);
    } while (++f != done);
  };
  std::vector<char> pinched(static_cast<size_t>(components), 0);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    std::unordered_map<int, int> sectors;
    for_each_sector_end(
        v, [](const FaceHandle& f) { return f->info().component; }, [&](int c) { ++sectors[c]; });
    for (const auto& [c, count] : sectors) {
      if (count > 1) pinched[static_cast<size_t>(c)] = 1;
    }
  }
  int pieces = 0;
  std::vector<int> piece_stamp(static_cast<size_t>(vertex_count), -1);  // Piece of the count.
  std::vector<int> piece_count(static_cast<size_t>(vertex_count), 0);   // Triangles at vertex.
  std::vector<int> component_piece(static_cast<size_t>(components), -1);
  auto count_at = [&](const VertexHandle& v, int piece) {
    const size_t k = static_cast<size_t>(v->info());
    return piece_stamp[k] == piece ? piece_count[k] : 0;
  };
  auto add = [&](const FaceHandle& f, int piece) {
    f->info().piece = piece;
    for (int i = 0; i < 3; ++i) {
      const size_t k = static_cast<size_t>(f->vertex(i)->info());
      if (piece_stamp[k] != piece) {
        piece_stamp[k] = piece;
        piece_count[k] = 0;
      }
      ++piece_count[k];
    }
  };
  // Triangle f may join `piece` if at each vertex the piece has no triangle yet or f shares an
  // unconstrained edge through that vertex with one of its triangles.
  auto may_join = [&](const FaceHandle& f, int piece) {
    for (int i = 0; i < 3; ++i) {
      if (count_at(f->vertex(i), piece) == 0) continue;
      bool adjacent = false;
      for (const int j : {TouchCdt::ccw(i), TouchCdt::cw(i)}) {  // The edges through vertex i.
        adjacent =
            adjacent || (f->neighbor(j)->info().piece == piece && !cdt.is_constrained({f, j}));
      }
      if (!adjacent) return false;
    }
    return true;
  };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int c = f->info().component;
    if (c < 0 || f->info().piece >= 0) continue;
    if (!pinched[static_cast<size_t>(c)]) {
      int& p = component_piece[static_cast<size_t>(c)];
      if (p < 0) p = pieces++;
      f->info().piece = p;
      continue;
    }
    const int piece = pieces++;
    add(f, piece);
    WalkTriangles(
        f,
        [&](const FaceHandle& g, int i) {
          const FaceHandle h = g->neighbor(i);
          if (h->info().component != c || h->info().piece >= 0 || cdt.is_constrained({g, i})) {
            return false;
          }
          if (!may_join(h, piece)) return false;  // Tried again when another neighbour joins.
          add(h, piece);
          return true;
        },
        &queue);
  }

  // A piece grown from one triangle cannot close around a hole (its two fronts meet at a vertex
  // where each already holds a sector), so a pinched part came out as about one piece per hole.
  // Pieces that share a cut are joined again wherever their union keeps one sector at every
  // vertex (tested at the vertices of the smaller), in passes until none joins: a pinch then
  // costs the cuts that separate its sectors, and the holes elsewhere stay holes.
  if (pieces > 1) {
    internal::DisjointSets joined(pieces);
    std::vector<std::vector<FaceHandle>> triangles_of(static_cast<size_t>(pieces));
    std::vector<std::pair<int, int>> cuts;  // Pieces across an unconstrained edge.
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      const int p = f->info().piece;
      if (p < 0 || !pinched[static_cast<size_t>(f->info().component)]) continue;
      triangles_of[static_cast<size_t>(p)].push_back(f);
      for (int i = 0; i < 3; ++i) {
        const int q = f->neighbor(i)->info().piece;
        if (q > p && !cdt.is_constrained({f, i})) cuts.emplace_back(p, q);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    std::vector<int> checked(static_cast<size_t>(vertex_count), -1);  // Stamp: attempt number.
    int attempt = 0;
    auto may_unite = [&](int a, int b) {
      ++attempt;
      const int small =
          triangles_of[static_cast<size_t>(a)].size() < triangles_of[static_cast<size_t>(b)].size()
              ? a
              : b;
      auto in_union = [&](const FaceHandle& f) {
        const int p = f->info().piece;
        if (p < 0) return -1;
        const int r = joined.Find(p);
        return r == a || r == b ? 0 : -1;
      };
      for (const FaceHandle& f : triangles_of[static_cast<size_t>(small)]) {
        for (int i = 0; i < 3; ++i) {
          const VertexHandle v = f->vertex(i);
          int& stamp = checked[static_cast<size_t>(v->info())];
          if (stamp == attempt) continue;
          stamp = attempt;
          int sectors = 0;
          for_each_sector_end(v, in_union, [&](int) { ++sectors; });
          if (sectors > 1) return false;
        }
      }
      return true;
    };
    // A pair refused is tried again only once one of its pieces has grown since: a piece's
    // version is the number of the last join it took part in.
    std::vector<int> version(static_cast<size_t>(pieces), 0);
    int joins = 0;
    std::vector<std::pair<int, int>> refused_at(cuts.size(), {-1, -1});
    for (bool again = true; again;) {
      again = false;
      for (size_t k = 0; k < cuts.size(); ++k) {
        const int a = joined.Find(cuts[k].first), b = joined.Find(cuts[k].second);
        if (a == b) continue;
        const std::pair<int, int> state{version[static_cast<size_t>(a)],
                                        version[static_cast<size_t>(b)]};
        if (refused_at[k] == state) continue;
        if (!may_unite(a, b)) {
          refused_at[k] = state;
          continue;
        }
        joined.Unite(a, b);
        const int root = joined.Find(a), other = root == a ? b : a;
        std::vector<FaceHandle>& into = triangles_of[static_cast<size_t>(root)];
        std::vector<FaceHandle>& from = triangles_of[static_cast<size_t>(other)];
        if (into.size() < from.size()) std::swap(into, from);  // Copy the smaller list.
        into.insert(into.end(), from.begin(), from.end());
        from = {};
        version[static_cast<size_t>(root)] = ++joins;
        again = true;
      }
    }
    // Pieces renumbered in order of their lowest original piece.
    std::vector<int> renumbered(static_cast<size_t>(pieces), -1);
    int count = 0;
    for (int p = 0; p < pieces; ++p) {
      if (joined.Find(p) == p) renumbered[static_cast<size_t>(p)] = count++;
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (f->info().piece >= 0) {
        f->info().piece = renumbered[static_cast<size_t>(joined.Find(f->info().piece))];
      }
    }
    pieces = count;
  }

  // Rings of each piece: its boundary edges, piece on the left, chained (one out-edge per
  // vertex, since every vertex has one sector). The ring through the lexicographically smallest
  // vertex is the outer one.
  std::vector<std::unordered_map<int, VertexHandle>> next_of(static_cast<size_t>(pieces));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int p = f->info().piece;
    if (p < 0) continue;
    for (int i = 0; i < 3; ++i) {
      if (f->neighbor(i)->info().piece == p) continue;
      next_of[static_cast<size_t>(p)][f->vertex(TouchCdt::ccw(i))->info()] =
          f->vertex(TouchCdt::cw(i));
    }
  }
  std::vector<VertexHandle> vertex_of(static_cast<size_t>(vertex_count));
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    vertex_of[static_cast<size_t>(v->info())] = v;
  }
  std::vector<Polygon2d> result;
  result.reserve(static_cast<size_t>(pieces));
  for (auto& next : next_of) {
    std::vector<Ring2d> loops;
    std::vector<CgalPoint> lowest;
    std::vector<int> starts;
    for (const auto& entry : next) starts.push_back(entry.first);
    std::sort(starts.begin(), starts.end());  // Deterministic order.
    std::unordered_map<int, char> used;
    for (const int start : starts) {
      if (used[start]) continue;
      Ring2d loop;
      CgalPoint low = vertex_of[static_cast<size_t>(start)]->point();
      int v = start;
      do {
        used[v] = 1;
        const CgalPoint& p = vertex_of[static_cast<size_t>(v)]->point();
        loop.emplace_back(p.x(), p.y());
        if (p < low) low = p;
        v = next.at(v)->info();
      } while (v != start);
      // Drop the vertices other rings added on this ring's straight edges.
      const IndexedRing cleaned = CleanRing(loop);
      Ring2d ring;
      for (const CgalPoint& p : cleaned.points) ring.emplace_back(p.x(), p.y());
      loops.push_back(std::move(ring));
      lowest.push_back(low);
    }
    size_t outer = 0;
    for (size_t k = 1; k < loops.size(); ++k) {
      if (lowest[k] < lowest[outer]) outer = k;
    }
    // The rings' areas were checked whole; a part split off at a touching point can still
    // have an area below what a double holds (subnormal coordinates beside normal ones:
    // fuzz_decompose2d), which nothing after could measure.
    for (const Ring2d& loop : loops) {
      if (SignedArea(loop) == 0.0) {
        Fail(where, "the part at " + internal::FormatPoint(loop.front()) +
                        ", split off where its rings touch, has zero area in double precision");
      }
    }
    Polygon2d polygon;
    polygon.outer = std::move(loops[outer]);
    for (size_t k = 0; k < loops.size(); ++k) {
      if (k != outer) polygon.holes.push_back(std::move(loops[k]));
    }
    result.push_back(std::move(polygon));
  }
  return result;
}

}  // namespace

void CheckCoordinates(const Polygon2d& raw, const std::string& where) {
  for (size_t r = 0; r <= raw.holes.size(); ++r) {
    const Ring2d& ring = r == 0 ? raw.outer : raw.holes[r - 1];
    for (size_t i = 0; i < ring.size(); ++i) {
      if (!std::isfinite(ring[i].x()) || !std::isfinite(ring[i].y())) {
        Fail(where, RingName(r) + ": vertex " + std::to_string(i) + " is not finite " +
                        internal::FormatPoint(ring[i]));
      }
      if (std::max(std::abs(ring[i].x()), std::abs(ring[i].y())) > kMaxCoordinate) {
        Fail(where, RingName(r) + ": vertex " + std::to_string(i) + " " +
                        internal::FormatPoint(ring[i]) +
                        " is too far from the origin (|coordinate| > 1e100: products of "
                        "coordinates would overflow)");
      }
    }
  }
}

std::vector<Polygon2d> PreparePolygons(const Polygon2d& raw, const std::string& where) {
  // 1. Every coordinate finite and at most kMaxCoordinate in magnitude.
  CheckCoordinates(raw, where);
  const size_t ring_count = 1 + raw.holes.size();
  auto raw_ring = [&](size_t r) -> const Ring2d& { return r == 0 ? raw.outer : raw.holes[r - 1]; };

  // 2. Clean and orient (outer counter-clockwise, holes clockwise); 3. enough vertices, area.
  std::vector<IndexedRing> rings;
  rings.reserve(ring_count);
  for (size_t r = 0; r < ring_count; ++r) {
    const Ring2d& input = raw_ring(r);
    IndexedRing ring = CleanRing(input);
    const std::string name = RingName(r);
    if (ring.size() < 3) {
      Fail(where, name + " has fewer than 3 distinct, non-collinear vertices (" +
                      std::to_string(ring.size()) + " distinct of " + std::to_string(input.size()) +
                      " remain after cleaning)");
    }
    if (TwiceArea(ring) == 0.0) Fail(where, name + " has zero area");
    const CGAL::Orientation wanted = r == 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE;
    if (RingOrientation(ring) != wanted) Reverse(ring);
    rings.push_back(std::move(ring));
  }
  const int last = static_cast<int>(ring_count) - 1;

  // 4.-6. Simplicity of each ring, holes inside the outer ring, holes disjoint. Rings that
  // meet anywhere take the slower path that accepts touchings at points.
  if (!RingsAreDisjointAndSimple(rings)) return PrepareTouching(std::move(rings), where);
  std::vector<CgalPoint> outer_points = rings[0].points;
  for (int h = 1; h <= last; ++h) {
    // No crossing or touching with the outer ring, so one vertex decides.
    const CgalPoint& p = rings[static_cast<size_t>(h)].points[0];
    if (CGAL::bounded_side_2(outer_points.begin(), outer_points.end(), p, Kernel()) !=
        CGAL::ON_BOUNDED_SIDE) {
      Fail(where, RingName(h) + " is not inside the outer ring: its vertex " +
                      std::to_string(rings[static_cast<size_t>(h)].input_index[0]) + " " +
                      internal::FormatPoint(Point2d(p.x(), p.y())) + " is outside");
    }
  }
  RejectNestedHoles(rings, where);

  Polygon2d clean;
  auto to_ring = [](const IndexedRing& ring) {
    Ring2d out;
    out.reserve(ring.size());
    for (const CgalPoint& p : ring.points) out.emplace_back(p.x(), p.y());
    return out;
  };
  clean.outer = to_ring(rings[0]);
  for (size_t r = 1; r < ring_count; ++r) clean.holes.push_back(to_ring(rings[r]));
  return {clean};
}

Polygon2d PreparePolygon(const Polygon2d& raw, const std::string& where) {
  std::vector<Polygon2d> pieces = PreparePolygons(raw, where);
  if (pieces.size() != 1) {
    Fail(where, "rings touch at points, which makes the polygon " + std::to_string(pieces.size()) +
                    " polygons where one is required (see PreparePolygons())");
  }
  return std::move(pieces[0]);
}

}  // namespace acdplan::acd
