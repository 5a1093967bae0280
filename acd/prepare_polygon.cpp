#include "acd/prepare_polygon.h"

#include <CGAL/Arr_non_caching_segment_traits_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Surface_sweep_2_algorithms.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "base/input_error.h"
#include "acd/internal/text_parsing.h"

namespace acdplan::acd {
namespace {

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

std::string RingName(int ring) {
  return ring == 0 ? "outer ring" : "hole " + std::to_string(ring - 1);
}

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

// Sort-by-x sweep with bounding boxes and exact do_intersect tests: O(n log n + k) for k
// pairs whose x-ranges overlap. Only called once a sweep (below) has found that something
// intersects, to name the edges.
std::optional<Hit> FindIntersection(const std::vector<IndexedRing>& rings,
                                    const std::vector<EdgeRef>& edges, bool only_between_rings) {
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
// report, since they meet at segment end points). The non-caching traits evaluate only
// kernel predicates on the input points, so the answer is exact with Epick.
bool RingsAreDisjointAndSimple(const std::vector<IndexedRing>& rings) {
  std::vector<CgalPoint> vertices;
  std::vector<CgalSegment> segments;
  for (const IndexedRing& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      vertices.push_back(ring.points[i]);
      segments.emplace_back(ring.points[i], ring.points[(i + 1) % ring.size()]);
    }
  }
  std::sort(vertices.begin(), vertices.end());
  if (std::adjacent_find(vertices.begin(), vertices.end()) != vertices.end()) return false;
  CGAL::Arr_non_caching_segment_traits_2<Kernel> traits;
  return !CGAL::do_curves_intersect(segments.begin(), segments.end(), traits);
}

}  // namespace

Polygon2d PreparePolygon(const Polygon2d& raw, const std::string& where) {
  // 1. Every coordinate finite.
  const size_t ring_count = 1 + raw.holes.size();
  auto raw_ring = [&](size_t r) -> const Ring2d& { return r == 0 ? raw.outer : raw.holes[r - 1]; };
  for (size_t r = 0; r < ring_count; ++r) {
    const Ring2d& ring = raw_ring(r);
    for (size_t i = 0; i < ring.size(); ++i) {
      if (!std::isfinite(ring[i].x()) || !std::isfinite(ring[i].y())) {
        Fail(where, RingName(static_cast<int>(r)) + ": vertex " + std::to_string(i) +
                        " is not finite " + internal::FormatPoint(ring[i]));
      }
    }
  }

  // 2. Clean and orient (outer counter-clockwise, holes clockwise); 3. enough vertices, area.
  std::vector<IndexedRing> rings;
  rings.reserve(ring_count);
  for (size_t r = 0; r < ring_count; ++r) {
    const Ring2d& input = raw_ring(r);
    IndexedRing ring = CleanRing(input);
    const std::string name = RingName(static_cast<int>(r));
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

  // 4.-6. Simplicity of each ring, holes inside the outer ring, holes disjoint.
  const bool disjoint = RingsAreDisjointAndSimple(rings);
  if (!disjoint) {
    for (int r = 0; r <= last; ++r) {
      if (const auto hit = FindIntersection(rings, EdgesOf(rings, r, r), false)) {
        Fail(where, RingName(r) + " is not simple: edges " + EdgeName(rings, hit->a) + " and " +
                        EdgeName(rings, hit->b) + Describe(*hit));
      }
    }
    for (int h = 1; h <= last; ++h) {
      std::vector<EdgeRef> edges = EdgesOf(rings, 0, 0);
      const std::vector<EdgeRef> hole = EdgesOf(rings, h, h);
      edges.insert(edges.end(), hole.begin(), hole.end());
      if (const auto hit = FindIntersection(rings, edges, true)) {
        Fail(where, RingName(h) +
                        " touches or crosses the outer ring (a hole must lie strictly "
                        "inside): outer edge " +
                        EdgeName(rings, hit->a) + " and hole edge " + EdgeName(rings, hit->b) +
                        Describe(*hit));
      }
    }
  }
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
  if (!disjoint) {
    if (const auto hit = FindIntersection(rings, EdgesOf(rings, 1, last), true)) {
      Fail(where, RingName(hit->a.ring) + " and " + RingName(hit->b.ring) +
                      " touch or overlap (holes must be disjoint): edges " +
                      EdgeName(rings, hit->a) + " and " + EdgeName(rings, hit->b) + Describe(*hit));
    }
    // The sweep saw something the pairwise search did not: should not happen.
    Fail(where, "rings intersect (internal inconsistency between the two intersection tests)");
  }
  // Disjoint holes are nested when one vertex of one lies inside the other.
  struct Box {
    double xmin, xmax, ymin, ymax;
  };
  std::vector<Box> boxes(ring_count);
  for (size_t r = 1; r < ring_count; ++r) {
    Box b{HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    for (const CgalPoint& p : rings[r].points) {
      b = {std::min(b.xmin, p.x()), std::max(b.xmax, p.x()), std::min(b.ymin, p.y()),
           std::max(b.ymax, p.y())};
    }
    boxes[r] = b;
  }
  for (size_t a = 1; a < ring_count; ++a) {
    for (size_t b = 1; b < ring_count; ++b) {
      if (a == b) continue;
      const CgalPoint& p = rings[a].points[0];
      const Box& box = boxes[b];
      if (p.x() < box.xmin || p.x() > box.xmax || p.y() < box.ymin || p.y() > box.ymax) continue;
      if (CGAL::bounded_side_2(rings[b].points.begin(), rings[b].points.end(), p, Kernel()) ==
          CGAL::ON_BOUNDED_SIDE) {
        Fail(where, RingName(static_cast<int>(a)) + " lies inside " +
                        RingName(static_cast<int>(b)) + " (holes must not be nested)");
      }
    }
  }

  Polygon2d clean;
  auto to_ring = [](const IndexedRing& ring) {
    Ring2d out;
    out.reserve(ring.size());
    for (const CgalPoint& p : ring.points) out.emplace_back(p.x(), p.y());
    return out;
  };
  clean.outer = to_ring(rings[0]);
  for (size_t r = 1; r < ring_count; ++r) clean.holes.push_back(to_ring(rings[r]));
  return clean;
}

}  // namespace acdplan::acd
