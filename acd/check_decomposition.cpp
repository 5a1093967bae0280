#include "acd/check_decomposition.h"

// What a clean result of CheckDecomposition() proves, per input polygon P and its components
// C_1..C_m (components of different input polygons are not compared with each other: each input
// polygon is decomposed on its own):
//
//  1. Every C_i is a simple polygon (exact predicates), so it has a well defined interior and
//     Area(C_i) is its measure.
//  2. C_i lies inside P: no vertex, edge point or interior sample of C_i lies outside P, no edge
//     of C_i properly crosses an edge of P, and no point of P's boundary (vertices, midpoints of
//     the edge pieces between component vertices, a sample inside each hole of P) lies strictly
//     inside C_i. Together: C_i is contained in P up to the distance tolerance.
//  3. Interiors are pairwise disjoint. Why the tests below suffice: if int A and int B meet,
//     the boundary of A n B consists of stretches of dA lying in closure(B) and of dB lying in
//     closure(A). Either some such stretch lies in the interior of the other polygon - then a
//     boundary point of one is strictly inside the other, or dA and dB properly cross - or all
//     of it lies on dA n dB, and there both interiors are on the same side of the shared
//     stretch, i.e. A and B traverse it in the same direction. The check therefore
//       - reports proper crossings (exact signs) of edges of two components;
//       - splits every edge at the vertices of other components lying on it, so each piece is
//         wholly inside, on, or outside each other component, and tests every vertex and every
//         piece midpoint for lying strictly inside another component;
//       - reports shared stretches traversed in the same direction (confirmed by a point just
//         beside the stretch lying strictly inside both, so slivers thinner than the tolerance
//         do not count);
//       - tests one deep interior sample of each component against the others (a second
//         witness for duplicated components).
//     A proper crossing with an end point within the tolerance of the other edge is rounding at
//     a T-junction or along a shared cut; it is left to the point tests, which still see any
//     deep overlap through a vertex or piece midpoint strictly inside.
//  4. Sum of Area(C_i) equals Area(P) to 1e-9 relative.
// From 2 and 3, Area(union C_i) = sum Area(C_i) = Area(P) and union C_i is a subset of P, so
// union C_i = P up to a set of measure ~ tolerance * perimeter: the components tile the input.
//
// Tolerances: topology (orientation, simplicity, crossing signs, inside/outside parity) is
// decided exactly with CGAL's Epick predicates. Distances are compared with
// tol = 1e-9 * ReferenceRadius(P) + 1e-12 * (largest |coordinate| of P), which absorbs the
// rounding of cut end points computed on edges (a Steiner point is within a few ulps of its
// edge), and nothing a real error would produce.

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>
#include <utility>

#include "acd/concavity.h"
#include "acd/concavity_measure.h"
#include "acd/internal/box_sweep.h"
#include "acd/internal/exact_predicates.h"
#include "acd/internal/problem_list.h"
#include "acd/internal/ring_locator.h"
#include "acd/internal/rounding_noise.h"
#include "base/format.h"

namespace acdplan::acd {
namespace {

using internal::IdBox;
using internal::Kernel;
using internal::MaxAbs;
using internal::Orientation;
using internal::PointLocation;
using internal::RayCrossesEdge;
using internal::RingLocator;
using internal::SegmentBox;
using internal::SegmentDistance;
using internal::ToCgal;

constexpr double kRelative = 1e-9;    // Areas, centroids, tau, distances (x reference radius).
constexpr double kHullNoise = 1e-12;  // Hull containment (x coordinate magnitude).

std::string Num(double v) { return FormatSignificant(v, 12); }

std::string Pt(const Point2d& p) { return "(" + Num(p.x()) + ", " + Num(p.y()) + ")"; }

using internal::ProblemList;

// Ring r of a polygon: 0 is the outer boundary, h + 1 is hole h.
const Ring2d& RingOf(const Polygon2d& polygon, int r) {
  return r == 0 ? polygon.outer : polygon.holes[r - 1];
}

std::string EdgeName(const Polygon2d& polygon, int ring, int index) {
  const int n = static_cast<int>(RingOf(polygon, ring).size());
  std::string name = "(" + std::to_string(index) + "," + std::to_string((index + 1) % n) + ")";
  return ring == 0 ? name : "hole " + std::to_string(ring - 1) + " " + name;
}

bool AllFinite(const Ring2d& ring) {
  for (const Point2d& p : ring) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
  }
  return true;
}

double MaxAbsCoordinate(const Polygon2d& polygon) {
  double m = 0.0;
  for (const Point2d& p : polygon.outer) m = std::max(m, MaxAbs(p));
  for (const Ring2d& hole : polygon.holes) {
    for (const Point2d& p : hole) m = std::max(m, MaxAbs(p));
  }
  return m;
}

CGAL::Bbox_2 BoundingBox(const Ring2d& ring) {
  CGAL::Bbox_2 box(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity());
  for (const Point2d& p : ring) box += CGAL::Bbox_2(p.x(), p.y(), p.x(), p.y());
  return box;
}

IdBox ToIdBox(const CGAL::Bbox_2& box, int id, double grow = 0.0) {
  return {{box.xmin() - grow, box.ymin() - grow}, {box.xmax() + grow, box.ymax() + grow}, id};
}

// Intersection point of the lines through [a, b] and [c, d] (which properly cross).
Point2d CrossingPoint(const Point2d& a, const Point2d& b, const Point2d& c, const Point2d& d) {
  const Point2d r = b - a, s = d - c;
  const double denominator = r.x() * s.y() - r.y() * s.x();
  const Point2d ac = c - a;
  const double t = (ac.x() * s.y() - ac.y() * s.x()) / denominator;
  return a + t * r;
}

// Exact even-odd parity of p against one ring.
bool InsideRing(const Ring2d& ring, const Point2d& p) {
  bool inside = false;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    if (RayCrossesEdge(p, ring[i], ring[(i + 1) % n])) inside = !inside;
  }
  return inside;
}

// Indices of the convex hull vertices of `ring` (Andrew's monotone chain with exact
// orientations), counter-clockwise, without collinear vertices. Independent of ConvexHull().
std::vector<int> HullIndices(const Ring2d& ring) {
  std::vector<int> order(ring.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return std::make_pair(ring[i].x(), ring[i].y()) < std::make_pair(ring[j].x(), ring[j].y());
  });
  if (order.size() < 3) return order;
  std::vector<int> hull(2 * order.size());
  size_t k = 0;
  for (int i : order) {  // Lower chain.
    while (k >= 2 && Orientation(ring[hull[k - 2]], ring[hull[k - 1]], ring[i]) <= 0) --k;
    hull[k++] = i;
  }
  const size_t lower = k + 1;
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) {  // Upper chain.
    while (k >= lower && Orientation(ring[hull[k - 2]], ring[hull[k - 1]], ring[*it]) <= 0) --k;
    hull[k++] = *it;
  }
  hull.resize(k - 1);
  return hull;
}

double HullArea(const Ring2d& ring, const std::vector<int>& hull) {
  Ring2d points;
  points.reserve(hull.size());
  for (int i : hull) points.push_back(ring[i]);
  return SignedArea(points);
}

// A point well inside `polygon`: on each of nine horizontal lines, the midpoint of the longest
// inside interval; the one farthest from the boundary wins. Returns the point and its distance
// to the boundary (0 if no line found an interval).
std::pair<Point2d, double> InteriorSample(const Polygon2d& polygon, const RingLocator& locator) {
  const CGAL::Bbox_2 box = BoundingBox(polygon.outer);
  std::vector<double> lines;
  for (int j = 0; j < 8; ++j)
    lines.push_back(box.ymin() + (j + 0.5) / 8.0 * (box.ymax() - box.ymin()));
  if (Area(polygon) > 0.0) lines.push_back(Centroid(polygon).y());
  Point2d best = polygon.outer.front();
  double best_depth = -1.0;
  std::vector<double> xs;
  for (double y : lines) {
    xs.clear();
    for (int r = 0; r <= static_cast<int>(polygon.holes.size()); ++r) {
      const Ring2d& ring = RingOf(polygon, r);
      const size_t n = ring.size();
      for (size_t i = 0; i < n; ++i) {
        const Point2d& a = ring[i];
        const Point2d& b = ring[(i + 1) % n];
        if ((a.y() > y) == (b.y() > y)) continue;
        xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
    std::sort(xs.begin(), xs.end());
    double longest = 0.0;
    double mid = 0.0;
    for (size_t i = 0; i + 1 < xs.size(); i += 2) {
      if (xs[i + 1] - xs[i] > longest) {
        longest = xs[i + 1] - xs[i];
        mid = 0.5 * (xs[i] + xs[i + 1]);
      }
    }
    if (!(longest > 0.0)) continue;
    const Point2d candidate(mid, y);
    if (!locator.InsideParity(candidate)) continue;
    const double depth = locator.BoundaryDistance(candidate);
    if (depth > best_depth) {
      best_depth = depth;
      best = candidate;
    }
  }
  return {best, std::max(best_depth, 0.0)};
}

struct InputInfo {
  double area = 0.0;
  double tolerance = 0.0;
  double scale = 0.0;  // Reference radius + largest |coordinate|.
  std::unique_ptr<RingLocator> locator;
};

struct ComponentInfo {
  bool usable = false;  // Finite, valid source, rings of >= 3 vertices: enters geometric tests.
  bool valid = false;   // Usable, counter-clockwise, simple, holes clockwise and inside.
  double tolerance = 0.0;
  double magnitude = 0.0;  // Largest |coordinate| plus the bounding box diagonal.
  double area = 0.0;
  CGAL::Bbox_2 box;
  std::unique_ptr<RingLocator> locator;
};

// An edge of a component (owner < components) or of an input polygon (owner = components + s).
struct EdgeRef {
  int owner, ring, index;
  Point2d a, b;
};

// A point on a boundary (a vertex, a midpoint of an edge piece) or an interior sample.
struct TestPoint {
  enum Kind { kVertex, kEdgePoint, kSample } kind;
  int owner, ring, index;
  Point2d p;
};

class Checker {
 public:
  Checker(const std::vector<Polygon2d>& input, const Decomposition2d& decomposition)
      : input_(input), d_(decomposition), components_(decomposition.components) {}

  std::vector<std::string> Run() && {
    PrepareInputs();
    CheckComponentRings();
    SweepEdges();
    CheckHolesInside();
    LocateBoundaryPoints();
    ReportSweep();
    CheckHullsAndCentroids();
    CheckAreas();
    CheckConcavity();
    CheckOpenings();
    CheckStats();
    return std::move(problems_).Finish();
  }

 private:
  int ComponentCount() const { return static_cast<int>(components_.size()); }
  bool IsComponent(int owner) const { return owner < ComponentCount(); }
  int SourceOf(int owner) const {
    return IsComponent(owner) ? components_[owner].source : owner - ComponentCount();
  }
  double ToleranceOf(int owner) const {
    return IsComponent(owner) ? info_[owner].tolerance
                              : inputs_[owner - ComponentCount()].tolerance;
  }
  const Polygon2d& PolygonOf(int owner) const {
    return IsComponent(owner) ? components_[owner].polygon : input_[owner - ComponentCount()];
  }
  std::string Label(int k) const { return "component " + std::to_string(k) + ": "; }

  void PrepareInputs() {
    for (const Polygon2d& polygon : input_) {
      InputInfo info;
      info.area = Area(polygon);
      const double radius = ReferenceRadius(polygon);
      const double magnitude = MaxAbsCoordinate(polygon);
      info.tolerance = kRelative * radius + kHullNoise * magnitude;
      info.scale = radius + magnitude;
      info.locator = std::make_unique<RingLocator>(polygon);
      inputs_.push_back(std::move(info));
    }
  }

  void CheckComponentRings() {
    info_.resize(components_.size());
    for (int k = 0; k < ComponentCount(); ++k) {
      const Component2d& c = components_[k];
      ComponentInfo& info = info_[k];
      if (c.source < 0 || c.source >= static_cast<int>(input_.size())) {
        problems_.Add(Label(k) + "source " + std::to_string(c.source) + " is not an input index (" +
                      std::to_string(input_.size()) + " input polygons)");
        continue;
      }
      bool finite = AllFinite(c.polygon.outer);
      for (const Ring2d& hole : c.polygon.holes) finite = finite && AllFinite(hole);
      if (!finite) {
        problems_.Add(Label(k) + "has a non-finite coordinate");
        continue;
      }
      bool sizes_ok = true;
      if (c.polygon.outer.size() < 3) {
        problems_.Add(Label(k) + "outer boundary has " + std::to_string(c.polygon.outer.size()) +
                      " vertices (needs >= 3)");
        sizes_ok = false;
      }
      for (size_t h = 0; h < c.polygon.holes.size(); ++h) {
        if (c.polygon.holes[h].size() < 3) {
          problems_.Add(Label(k) + "hole " + std::to_string(h) + " has " +
                        std::to_string(c.polygon.holes[h].size()) + " vertices (needs >= 3)");
          sizes_ok = false;
        }
      }
      if (!sizes_ok) continue;
      info.usable = true;
      info.valid = true;
      info.tolerance = inputs_[c.source].tolerance;
      info.box = BoundingBox(c.polygon.outer);
      info.magnitude = MaxAbsCoordinate(c.polygon) + std::hypot(info.box.xmax() - info.box.xmin(),
                                                                info.box.ymax() - info.box.ymin());
      info.area = Area(c.polygon);
      info.locator = std::make_unique<RingLocator>(c.polygon);
      // The sign of a ring's area, exactly where its double underflows to 0: a sliver cut from a
      // polygon with coordinates near the smallest doubles (fuzz_decompose2d) has an area no
      // double holds, and is still a valid counter-clockwise ring.
      auto area_sign = [](const Ring2d& ring, double area) {
        return area != 0.0 ? (area > 0.0 ? 1 : -1) : internal::RingOrientation(ring);
      };
      const double outer_area = SignedArea(c.polygon.outer);
      if (const int sign = area_sign(c.polygon.outer, outer_area); sign <= 0) {
        problems_.Add(Label(k) + (sign == 0 ? "outer boundary has zero area"
                                            : "outer boundary is clockwise (signed area " +
                                                  Num(outer_area) + ")"));
        info.valid = false;
      }
      for (size_t h = 0; h < c.polygon.holes.size(); ++h) {
        const double hole_area = SignedArea(c.polygon.holes[h]);
        if (area_sign(c.polygon.holes[h], hole_area) >= 0) {
          problems_.Add(Label(k) + "hole " + std::to_string(h) + " is not clockwise (signed area " +
                        Num(hole_area) + ")");
          info.valid = false;
        }
      }
    }
  }

  // --- Edge pairs: simplicity, proper crossings, shared stretches. ---

  void SweepEdges() {
    const int count = ComponentCount();
    auto add_polygon = [this](int owner, const Polygon2d& polygon) {
      for (int r = 0; r <= static_cast<int>(polygon.holes.size()); ++r) {
        const Ring2d& ring = RingOf(polygon, r);
        const int n = static_cast<int>(ring.size());
        for (int i = 0; i < n; ++i) edges_.push_back({owner, r, i, ring[i], ring[(i + 1) % n]});
      }
    };
    for (int k = 0; k < count; ++k) {
      if (info_[k].usable) add_polygon(k, components_[k].polygon);
    }
    for (int s = 0; s < static_cast<int>(input_.size()); ++s) {
      if (AllFinite(input_[s].outer)) add_polygon(count + s, input_[s]);
    }
    std::vector<IdBox> boxes;
    boxes.reserve(edges_.size());
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      boxes.push_back(SegmentBox(edges_[e].a, edges_[e].b, e));
    }
    internal::ForEachSelfOverlap(std::move(boxes), [this](int e, int f) {
      if (e > f) std::swap(e, f);  // Edges are numbered by (owner, ring, index).
      PairOfEdges(edges_[e], edges_[f]);
    });
  }

  void PairOfEdges(const EdgeRef& e, const EdgeRef& f) {
    const bool e_component = IsComponent(e.owner), f_component = IsComponent(f.owner);
    if (!e_component && !f_component) return;  // Input edges are trusted (PreparePolygon()).
    if (e.owner == f.owner) {
      SelfPair(e, f);
      return;
    }
    if (SourceOf(e.owner) != SourceOf(f.owner)) return;
    // The common case, decided without predicates: a cut shared by two components (reversed)
    // or a component edge on the input boundary (same direction).
    if (e.a == f.b && e.b == f.a) return;
    if (e.a == f.a && e.b == f.b) {
      if (e_component && f_component) SameDirectionStretch(e, f, ToleranceOf(e.owner));
      return;
    }
    const double tolerance = ToleranceOf(e.owner);
    const bool touching = SegmentDistance(e.a, f.a, f.b) <= tolerance ||
                          SegmentDistance(e.b, f.a, f.b) <= tolerance ||
                          SegmentDistance(f.a, e.a, e.b) <= tolerance ||
                          SegmentDistance(f.b, e.a, e.b) <= tolerance;
    if (touching) {
      // An end point within the tolerance of the other edge: a T-junction (a cut end point
      // computed on an edge) or a shared stretch, where rounding may make the edges cross
      // "properly" by a hair. Not a crossing; a deep overlap that also has such an end point is
      // found by LocateBoundaryPoints(), where some vertex or edge point lies strictly inside.
      // What remains to test: two components running along a shared stretch (within the
      // tolerance, longer than it) in the same direction have their interiors on the same side.
      if (e_component && f_component) SameDirectionStretch(e, f, tolerance);
      return;
    }
    const int o1 = Orientation(e.a, e.b, f.a), o2 = Orientation(e.a, e.b, f.b);
    if (o1 * o2 >= 0) return;
    const int o3 = Orientation(f.a, f.b, e.a), o4 = Orientation(f.a, f.b, e.b);
    if (o3 * o4 >= 0) return;
    // A proper crossing (exact) with every end point farther than the tolerance from the other
    // edge, so also the crossing point is farther than that from all four end points.
    const Point2d p = CrossingPoint(e.a, e.b, f.a, f.b);
    if (e_component && f_component) {
      AddOverlap(e.owner, f.owner, p);
    } else {
      const int component = e_component ? e.owner : f.owner;
      AddLeave(component, 1,
               "edge crosses the boundary of input polygon " + std::to_string(SourceOf(component)) +
                   " at " + Pt(p),
               p);
    }
  }

  void SameDirectionStretch(const EdgeRef& e, const EdgeRef& f, double tolerance) {
    const double length = (e.b - e.a).norm();
    if (!(length > 0.0) || f.a == f.b) return;
    const Point2d u = (e.b - e.a) / length;
    const Point2d n(-u.y(), u.x());
    if (u.dot(f.b - f.a) <= 0.0) return;  // Opposite directions: the usual shared cut.
    // f in e's frame: along-track s, cross-track h (linear in s).
    const double s1 = (f.a - e.a).dot(u), s2 = (f.b - e.a).dot(u);
    const double h1 = (f.a - e.a).dot(n), h2 = (f.b - e.a).dot(n);
    const double lo = std::max(0.0, s1), hi = std::min(length, s2);  // s1 < s2 here.
    if (!(hi - lo > tolerance)) return;
    auto h = [&](double s) { return h1 + (s - s1) / (s2 - s1) * (h2 - h1); };
    if (!(std::abs(h(lo)) <= tolerance && std::abs(h(hi)) <= tolerance)) return;
    // Both interiors are on the left of the stretch. Report the overlap only if a point a few
    // tolerances to that side is strictly inside both: a sliver thinner than the tolerance
    // (rounding noise, zero area to 1e-16) overlaps nothing.
    const Point2d q = e.a + 0.5 * (lo + hi) * u + 3.0 * tolerance * n;
    if (info_[e.owner].locator->Locate(q, tolerance) == PointLocation::kInside &&
        info_[f.owner].locator->Locate(q, tolerance) == PointLocation::kInside) {
      AddOverlap(e.owner, f.owner, q);
    }
  }

  void SelfPair(const EdgeRef& e, const EdgeRef& f) {
    const Polygon2d& polygon = components_[e.owner].polygon;
    auto names = [&] {
      return "edges " + EdgeName(polygon, e.ring, e.index) + " and " +
             EdgeName(polygon, f.ring, f.index);
    };
    const auto key = std::make_tuple(e.ring, e.index, f.ring, f.index);
    if (e.ring == f.ring) {
      const int n = static_cast<int>(RingOf(polygon, e.ring).size());
      const EdgeRef* first = nullptr;
      const EdgeRef* second = nullptr;
      if ((e.index + 1) % n == f.index) {
        first = &e, second = &f;
      } else if ((f.index + 1) % n == e.index) {
        first = &f, second = &e;
      }
      if (first != nullptr) {  // Adjacent: they may only share their common vertex.
        const Point2d& u = first->a;
        const Point2d& v = first->b;
        const Point2d& w = second->b;
        if (u == v || v == w) {
          const EdgeRef& zero = u == v ? *first : *second;
          AddSelf(e.owner, key,
                  "vertex " + std::to_string((zero.index + 1) % n) + " repeats vertex " +
                      std::to_string(zero.index) + " at " + Pt(zero.a));
        } else if (Orientation(u, v, w) == 0 && !CGAL::collinear_are_strictly_ordered_along_line(
                                                    ToCgal(u), ToCgal(v), ToCgal(w))) {
          AddSelf(e.owner, key, names() + " overlap (spike at " + Pt(v) + ")");
        }
        return;
      }
    }
    if (e.a == e.b || f.a == f.b) return;  // Reported by the adjacent pair.
    const Kernel::Segment_2 s(ToCgal(e.a), ToCgal(e.b)), t(ToCgal(f.a), ToCgal(f.b));
    if (!CGAL::do_intersect(s, t)) return;
    const int o1 = Orientation(e.a, e.b, f.a), o2 = Orientation(e.a, e.b, f.b);
    const int o3 = Orientation(f.a, f.b, e.a), o4 = Orientation(f.a, f.b, e.b);
    if (o1 * o2 < 0 && o3 * o4 < 0) {
      AddSelf(e.owner, key, names() + " cross at " + Pt(CrossingPoint(e.a, e.b, f.a, f.b)));
      return;
    }
    // Touching or collinear overlap: name a shared point.
    Point2d p = e.a;
    if (o3 == 0 && SegmentDistance(e.b, f.a, f.b) == 0.0) p = e.b;
    if (o1 == 0 && SegmentDistance(f.a, e.a, e.b) == 0.0) p = f.a;
    if (o2 == 0 && SegmentDistance(f.b, e.a, e.b) == 0.0) p = f.b;
    AddSelf(e.owner, key, names() + " touch at " + Pt(p));
  }

  // --- Boundary points strictly inside another component, or outside the input. ---

  void LocateBoundaryPoints() {
    const int count = ComponentCount();
    // Split points: vertices of other owners (same source) lying on an edge's interior.
    std::vector<IdBox> edge_boxes, vertex_boxes;
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      const EdgeRef& edge = edges_[e];
      edge_boxes.push_back(SegmentBox(edge.a, edge.b, e, ToleranceOf(edge.owner)));
      vertex_boxes.push_back(SegmentBox(edge.a, edge.a, e));
    }
    std::vector<std::pair<int, double>> splits;  // (edge, parameter along it)
    internal::ForEachOverlap(
        std::move(edge_boxes), std::move(vertex_boxes), [&](int edge_id, int vertex_id) {
          const EdgeRef& edge = edges_[edge_id];
          const EdgeRef& vertex = edges_[vertex_id];
          if (edge.owner == vertex.owner || SourceOf(edge.owner) != SourceOf(vertex.owner)) return;
          if (!IsComponent(edge.owner) && !IsComponent(vertex.owner)) return;
          const double tolerance = ToleranceOf(edge.owner);
          const Point2d& p = vertex.a;
          if ((p - edge.a).norm() <= tolerance || (p - edge.b).norm() <= tolerance) return;
          if (SegmentDistance(p, edge.a, edge.b) > tolerance) return;
          const Point2d ab = edge.b - edge.a;
          splits.emplace_back(edge_id,
                              std::clamp((p - edge.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0));
        });
    std::sort(splits.begin(), splits.end());

    std::vector<TestPoint> points;
    size_t next_split = 0;
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      const EdgeRef& edge = edges_[e];
      points.push_back({TestPoint::kVertex, edge.owner, edge.ring, edge.index, edge.a});
      double t0 = 0.0;
      while (next_split < splits.size() && splits[next_split].first == e) {
        const double t1 = splits[next_split++].second;
        if (t1 > t0) {
          points.push_back({TestPoint::kEdgePoint, edge.owner, edge.ring, edge.index,
                            edge.a + 0.5 * (t0 + t1) * (edge.b - edge.a)});
        }
        t0 = t1;
      }
      points.push_back({TestPoint::kEdgePoint, edge.owner, edge.ring, edge.index,
                        edge.a + 0.5 * (t0 + 1.0) * (edge.b - edge.a)});
    }
    // Interior samples: one per valid component (witness for identical components), one per
    // hole of each input polygon (a component must not cover an input hole).
    for (int k = 0; k < count; ++k) {
      if (!info_[k].valid) continue;
      points.push_back({TestPoint::kSample, k, 0, -1,
                        InteriorSample(components_[k].polygon, *info_[k].locator).first});
    }
    for (int s = 0; s < static_cast<int>(input_.size()); ++s) {
      for (const Ring2d& hole : input_[s].holes) {
        if (hole.size() < 3 || !AllFinite(hole)) continue;
        const Polygon2d region{Reversed(hole), {}};
        const RingLocator locator(region);
        points.push_back(
            {TestPoint::kSample, count + s, 0, -1, InteriorSample(region, locator).first});
      }
    }

    // Component points must lie in their input polygon.
    for (const TestPoint& point : points) {
      if (!IsComponent(point.owner)) continue;
      const int source = SourceOf(point.owner);
      if (inputs_[source].locator->Locate(point.p, ToleranceOf(point.owner)) !=
          PointLocation::kOutside) {
        continue;
      }
      std::string what =
          point.kind == TestPoint::kVertex
              ? "vertex " + std::to_string(point.index) +
                    (point.ring == 0 ? "" : " of hole " + std::to_string(point.ring - 1))
          : point.kind == TestPoint::kSample ? "interior point"
                                             : "edge point";
      AddLeave(point.owner, point.kind == TestPoint::kVertex ? 0 : 2,
               what + " " + Pt(point.p) + " lies outside input polygon " + std::to_string(source),
               point.p);
    }

    // Every point against every other component of the same source whose box holds it.
    std::vector<IdBox> point_boxes, component_boxes;
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      point_boxes.push_back(SegmentBox(points[i].p, points[i].p, i));
    }
    for (int k = 0; k < count; ++k) {
      if (info_[k].usable) component_boxes.push_back(ToIdBox(info_[k].box, k, info_[k].tolerance));
    }
    internal::ForEachOverlap(
        std::move(point_boxes), std::move(component_boxes), [&](int point_id, int k) {
          const TestPoint& point = points[point_id];
          if (point.owner == k || SourceOf(point.owner) != components_[k].source) return;
          if (info_[k].locator->Locate(point.p, info_[k].tolerance) != PointLocation::kInside)
            return;
          if (IsComponent(point.owner)) {
            AddOverlap(point.owner, k, point.p);
          } else {
            AddLeave(
                k, 3,
                "covers " +
                    std::string(point.kind == TestPoint::kSample ? "a hole" : "a boundary point") +
                    " of input polygon " + std::to_string(SourceOf(point.owner)) + " at " +
                    Pt(point.p),
                point.p);
          }
        });
  }

  // --- Collected pair findings, reported in a deterministic order. ---

  using SelfKey = std::tuple<int, int, int, int>;
  void AddSelf(int k, const SelfKey& key, const std::string& what) {
    auto it = self_.find(k);
    if (it == self_.end() || key < it->second.first) self_[k] = {key, what};
  }
  void AddOverlap(int i, int j, const Point2d& p) {
    const auto pair = std::minmax(i, j);
    auto it = overlaps_.find(pair);
    if (it == overlaps_.end() ||
        std::make_pair(p.x(), p.y()) < std::make_pair(it->second.x(), it->second.y())) {
      overlaps_[pair] = p;
    }
  }
  void AddLeave(int k, int priority, const std::string& what, const Point2d& p) {
    const auto key = std::make_tuple(priority, p.x(), p.y());
    auto it = leaves_.find(k);
    if (it == leaves_.end() || key < it->second.first) leaves_[k] = {key, what};
  }

  void CheckHolesInside() {
    for (auto& [k, finding] : self_) info_[k].valid = false;
    for (int k = 0; k < ComponentCount(); ++k) {
      if (!info_[k].valid) continue;
      const Polygon2d& polygon = components_[k].polygon;
      // The rings do not meet (simplicity sweep), so one vertex decides for a whole hole.
      for (size_t h = 0; h < polygon.holes.size(); ++h) {
        const Point2d& p = polygon.holes[h].front();
        if (!InsideRing(polygon.outer, p)) {
          problems_.Add(Label(k) + "hole " + std::to_string(h) +
                        " is not inside the outer boundary");
          info_[k].valid = false;
          continue;
        }
        for (size_t g = 0; g < polygon.holes.size(); ++g) {
          if (g != h && InsideRing(polygon.holes[g], p)) {
            problems_.Add(Label(k) + "hole " + std::to_string(h) + " lies inside hole " +
                          std::to_string(g));
            info_[k].valid = false;
            break;
          }
        }
      }
    }
  }

  void ReportSweep() {
    for (const auto& [k, finding] : self_)
      problems_.Add(Label(k) + "not simple: " + finding.second);
    for (const auto& [pair, p] : overlaps_) {
      problems_.Add("components " + std::to_string(pair.first) + " and " +
                    std::to_string(pair.second) + " overlap near " + Pt(p));
    }
    for (const auto& [k, finding] : leaves_) problems_.Add(Label(k) + finding.second);
  }

  // --- Hull and centroid. ---

  void CheckHullsAndCentroids() {
    for (int k = 0; k < ComponentCount(); ++k) {
      if (!info_[k].valid) continue;
      const Component2d& c = components_[k];
      const double magnitude = info_[k].magnitude;
      const Point2d centroid = Centroid(c.polygon);
      if (!((c.centroid - centroid).norm() <= kRelative * magnitude)) {
        problems_.Add(Label(k) + "centroid " + Pt(c.centroid) + " != Centroid(polygon) " +
                      Pt(centroid));
      }
      const Ring2d& hull = c.hull;
      const int h = static_cast<int>(hull.size());
      if (h < 3 || !AllFinite(hull)) {
        problems_.Add(Label(k) + "hull has " + std::to_string(h) +
                      (h < 3 ? " vertices (needs >= 3)" : " vertices, some not finite"));
        continue;
      }
      bool convex = internal::RingOrientation(hull) > 0;  // (Exact: a sliver's area underflows.)
      int bad = 0;
      for (int i = 0; i < h && convex; ++i) {
        // Left turns everywhere and a fan from hull[0] without right turns: convex, winding once.
        if (Orientation(hull[i], hull[(i + 1) % h], hull[(i + 2) % h]) < 0 ||
            Orientation(hull[0], hull[i], hull[(i + 1) % h]) < 0) {
          convex = false;
          bad = (i + 1) % h;
        }
      }
      if (!convex) {
        problems_.Add(Label(k) + "hull is not convex counter-clockwise (at hull vertex " +
                      std::to_string(bad) + ")");
        continue;
      }
      // The hull contains the boundary iff it contains the boundary's own hull vertices, and
      // it suffices to test, per hull edge, the own-hull vertex farthest out along the edge's
      // outward normal. That vertex advances monotonically as the edges turn (rotating
      // calipers), so all edges cost O(h + m) instead of O(h m) for a 10,000-vertex piece.
      const std::vector<int> own = HullIndices(c.polygon.outer);
      const int m = static_cast<int>(own.size());
      auto outward = [&](int i, int j) {  // Signed distance beyond edge i (unnormalised).
        const Point2d& a = hull[i];
        const Point2d& b = hull[(i + 1) % h];
        const Point2d& p = c.polygon.outer[own[j]];
        return (b.y() - a.y()) * (p.x() - a.x()) - (b.x() - a.x()) * (p.y() - a.y());
      };
      int j = 0;
      for (int t = 1; t < m; ++t) {
        if (outward(0, t) > outward(0, j)) j = t;
      }
      bool contained = true;
      for (int i = 0; i < h && contained && m > 0; ++i) {
        for (int steps = 0; steps < m && outward(i, (j + 1) % m) > outward(i, j); ++steps) {
          j = (j + 1) % m;
        }
        const Point2d& a = hull[i];
        const Point2d& b = hull[(i + 1) % h];
        const Point2d& p = c.polygon.outer[own[j]];
        if (Orientation(a, b, p) >= 0) continue;
        const double distance = outward(i, j) / (b - a).norm();
        if (distance > kHullNoise * magnitude) {
          problems_.Add(Label(k) + "vertex " + std::to_string(own[j]) + " " + Pt(p) +
                        " lies outside its hull (by " + Num(distance) + " beyond hull edge " +
                        std::to_string(i) + ")");
          contained = false;
        }
      }
      if (!contained) continue;
      const double hull_area = SignedArea(hull);
      const double own_area = HullArea(c.polygon.outer, own);
      if (hull_area > own_area * (1.0 + kRelative) + kHullNoise * magnitude * magnitude) {
        problems_.Add(Label(k) + "hull area " + Num(hull_area) +
                      " exceeds the boundary's convex hull area " + Num(own_area));
      }
    }
  }

  // --- Coverage by area. ---

  // The components end cuts at points constructed on the input's edges, each rounded off its
  // edge: they tile the input with those points put into its boundary. That area differs from
  // the input's by each such edge's sliver, the signed area of the chain from the edge's start
  // through its points to its end: an offset of a rounding times the edge's length, which on an
  // edge 1.5e9 long exceeded the relative tolerance (fuzz_decompose2d). A constructed point is a
  // component vertex that is no input vertex; it goes to the nearest input edge of its source
  // within OnEdgeNoise() of it (none for a point inside), if the components' union has a
  // boundary edge from it along that edge. Signed so that a point outside the input adds area,
  // on any ring orientation. Returned per source with how much the components' area may differ
  // from the input's besides (`noise`): a constructed point where a cut of one component ends
  // on another's edge (a T-junction) is off that edge by its rounding, a triangle of at most
  // half its noise times the edge's length, which the component edges at the point bound. Where
  // a needle's sides lie closer than noise, a point on a cut from its foot can pass for a point
  // on the needle's edge, with a neighbour on it too (a needle 1e-14 wide at its foot, a cut's
  // point 1e-12 off its edge 5,500 long, fuzz_decompose2d): its sliver is credited in error,
  // which is why CheckAreas() also takes the input's area as it is.
  struct AreaCorrections {
    std::vector<double> slivers, noise;
  };
  AreaCorrections RoundingCorrections() const {
    const int count = ComponentCount();
    std::vector<std::pair<int, Point2d>> input_vertices;  // (source, vertex), sorted.
    std::vector<IdBox> edge_boxes;
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      const EdgeRef& edge = edges_[e];
      if (IsComponent(edge.owner)) continue;
      input_vertices.emplace_back(SourceOf(edge.owner), edge.a);
      // Padded by OnEdgeNoise() of any point of the edge, or more.
      const double pad =
          kHullNoise * std::max({MaxAbs(edge.a), MaxAbs(edge.b), MaxAbs(edge.b - edge.a), 1.0});
      edge_boxes.push_back(SegmentBox(edge.a, edge.b, e, pad));
    }
    auto key = [](const std::pair<int, Point2d>& v) {
      return std::make_tuple(v.first, v.second.x(), v.second.y());
    };
    auto before = [&](const auto& x, const auto& y) { return key(x) < key(y); };
    std::sort(input_vertices.begin(), input_vertices.end(), before);
    std::vector<std::pair<int, Point2d>> constructed;  // (source, point), each once.
    for (int k = 0; k < count; ++k) {
      if (!info_[k].usable) continue;
      const Polygon2d& polygon = components_[k].polygon;
      for (int r = 0; r <= static_cast<int>(polygon.holes.size()); ++r) {
        for (const Point2d& p : RingOf(polygon, r)) {
          const std::pair<int, Point2d> v(components_[k].source, p);
          if (!std::binary_search(input_vertices.begin(), input_vertices.end(), v, before)) {
            constructed.push_back(v);
          }
        }
      }
    }
    std::sort(constructed.begin(), constructed.end(), before);
    constructed.erase(std::unique(constructed.begin(), constructed.end(),
                                  [&](const auto& x, const auto& y) { return key(x) == key(y); }),
                      constructed.end());
    std::vector<IdBox> point_boxes;
    for (int i = 0; i < static_cast<int>(constructed.size()); ++i) {
      point_boxes.push_back(SegmentBox(constructed[i].second, constructed[i].second, i));
    }
    // Per constructed point: its nearest input edge within noise, or -1. Nearest exactly: near
    // a corner, two edges' distances may differ by less than their rounding.
    std::vector<int> nearest(constructed.size(), -1);
    auto segment = [this](int e) {
      return Kernel::Segment_2(ToCgal(edges_[e].a), ToCgal(edges_[e].b));
    };
    internal::ForEachOverlap(std::move(edge_boxes), std::move(point_boxes), [&](int e, int i) {
      const EdgeRef& edge = edges_[e];
      const Point2d& p = constructed[i].second;
      if (SourceOf(edge.owner) != constructed[i].first) return;
      // Exactly: a distance in floating point errs by the rounding of the far end's coordinates.
      const double noise = OnEdgeNoise(edge, p);
      const Kernel::Point_2 q = ToCgal(p);
      const Kernel::Segment_2 s = segment(e);
      const auto compare = Kernel().compare_squared_distance_2_object();
      if (compare(q, s, noise * noise) == CGAL::LARGER) return;
      int& best = nearest[i];
      const CGAL::Comparison_result order =
          best < 0 ? CGAL::SMALLER : compare(q, s, q, segment(best));
      if (order == CGAL::SMALLER || (order == CGAL::EQUAL && e < best)) best = e;
    });
    // Per constructed point: whether a component's edge runs straight through it (exactly; not
    // within noise, which a long edge's is wide enough to take in the cut ends beside it). That
    // edge is not split at the point, so the components' boundary does not bend there: a cut's
    // point 3.6e-22 from an edge 5.6e21 long, on the diagonal that closes off the needle, would
    // add a sliver of area 1.
    std::vector<char> passed_through(constructed.size(), 0);
    std::vector<IdBox> component_edge_boxes, near_points;
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      const EdgeRef& edge = edges_[e];
      if (!IsComponent(edge.owner)) continue;
      component_edge_boxes.push_back(SegmentBox(edge.a, edge.b, e));
    }
    for (int i = 0; i < static_cast<int>(constructed.size()); ++i) {
      if (nearest[i] >= 0) {
        near_points.push_back(SegmentBox(constructed[i].second, constructed[i].second, i));
      }
    }
    internal::ForEachOverlap(
        std::move(component_edge_boxes), std::move(near_points), [&](int e, int i) {
          const EdgeRef& edge = edges_[e];
          const Point2d& p = constructed[i].second;
          if (p == edge.a || p == edge.b || SourceOf(edge.owner) != constructed[i].first) return;
          if (segment(e).has_on(ToCgal(p))) passed_through[i] = 1;
        });
    // Per constructed point near an input edge: whether the union's boundary runs along that
    // edge at the point, i.e. an edge of a component that no other component has reversed (not
    // a cut between two of them) joins it to a point of the input edge. A cut's end inside a
    // needle (3.5e-6 wide, fuzz_decompose2d) can lie within noise of an edge; it splits no edge,
    // and its sliver would be area the components do not miss.
    using PointKey = std::tuple<int, double, double>;  // (source, x, y).
    auto key_of = [this](int owner, const Point2d& p) {
      return PointKey(SourceOf(owner), p.x(), p.y());
    };
    std::vector<std::pair<PointKey, PointKey>> component_edges;  // Directed, sorted.
    std::map<PointKey, double> incident_length;  // Of the component edges at a point.
    for (const EdgeRef& edge : edges_) {
      if (!IsComponent(edge.owner)) continue;
      component_edges.emplace_back(key_of(edge.owner, edge.a), key_of(edge.owner, edge.b));
      const double length = (edge.b - edge.a).norm();
      incident_length[component_edges.back().first] += length;
      incident_length[component_edges.back().second] += length;
    }
    std::sort(component_edges.begin(), component_edges.end());
    std::map<PointKey, std::vector<Point2d>> boundary_neighbours;  // Ends of unmatched edges.
    for (const EdgeRef& edge : edges_) {
      if (!IsComponent(edge.owner)) continue;
      const auto reversed = std::make_pair(key_of(edge.owner, edge.b), key_of(edge.owner, edge.a));
      if (std::binary_search(component_edges.begin(), component_edges.end(), reversed)) continue;
      boundary_neighbours[key_of(edge.owner, edge.a)].push_back(edge.b);
      boundary_neighbours[key_of(edge.owner, edge.b)].push_back(edge.a);
    }
    auto on_boundary_along = [&](int i, int e) {
      const EdgeRef& edge = edges_[e];
      const auto it = boundary_neighbours.find(
          PointKey(constructed[i].first, constructed[i].second.x(), constructed[i].second.y()));
      if (it == boundary_neighbours.end()) return false;
      for (const Point2d& q : it->second) {
        if (q == edge.a || q == edge.b) return true;
        const double noise = OnEdgeNoise(edge, q);
        if (Kernel().compare_squared_distance_2_object()(ToCgal(q), segment(e), noise * noise) !=
            CGAL::LARGER) {
          return true;
        }
      }
      return false;
    };
    // The points on each edge that it is split at, in order along it.
    struct OnEdge {
      int edge;
      double along;  // Parameter along the edge, 0 at its start and 1 at its end.
      Point2d point;
      auto Key() const { return std::make_tuple(edge, along, point.x(), point.y()); }
    };
    std::vector<OnEdge> on_edges;
    for (size_t i = 0; i < constructed.size(); ++i) {
      const int e = nearest[i];
      if (e < 0 || passed_through[i] || !on_boundary_along(static_cast<int>(i), e)) continue;
      const Point2d ab = edges_[e].b - edges_[e].a;
      const Point2d& p = constructed[i].second;
      on_edges.push_back({e, (p - edges_[e].a).dot(ab) / ab.squaredNorm(), p});
    }
    std::sort(on_edges.begin(), on_edges.end(),
              [](const OnEdge& x, const OnEdge& y) { return x.Key() < y.Key(); });
    AreaCorrections out{std::vector<double>(input_.size(), 0.0),
                        std::vector<double>(input_.size(), 0.0)};
    std::vector<double>& slivers = out.slivers;
    for (const auto& [source, p] : constructed) {
      const double noise = kHullNoise * std::max(MaxAbs(p), 1.0);
      out.noise[static_cast<size_t>(source)] +=
          0.5 * noise * incident_length[PointKey(source, p.x(), p.y())];
    }
    std::map<std::pair<int, int>, bool> interior_left;  // Per (owner, ring) met.
    for (size_t first = 0; first < on_edges.size();) {
      const int e = on_edges[first].edge;
      const EdgeRef& edge = edges_[e];
      Ring2d chain = {edge.a};
      size_t last = first;
      for (; last < on_edges.size() && on_edges[last].edge == e; ++last) {
        chain.push_back(on_edges[last].point);
      }
      chain.push_back(edge.b);
      const auto [ring, unseen] = interior_left.try_emplace({edge.owner, edge.ring}, false);
      if (unseen) {
        // The interior lies left of a counter-clockwise outer ring and of a clockwise hole.
        const double ring_area = SignedArea(RingOf(PolygonOf(edge.owner), edge.ring));
        ring->second = (ring_area > 0.0) == (edge.ring == 0);
      }
      const double sliver = SignedArea(chain);
      slivers[static_cast<size_t>(SourceOf(edge.owner))] += ring->second ? sliver : -sliver;
      first = last;
    }
    return out;
  }

  // How far a point constructed on `edge` may lie off it: rounding noise of its coordinates and
  // of its offset from the nearer end of the edge, which it is constructed from (Resolve()), a
  // thousand times the unit roundoff. Not the magnitude of the far end: an edge to 5.6e21 would
  // then claim every point within 5.6e9 of it.
  static double OnEdgeNoise(const EdgeRef& edge, const Point2d& p) {
    const double offset = std::min(MaxAbs(p - edge.a), MaxAbs(p - edge.b));
    return kHullNoise * std::max({MaxAbs(p), offset, 1.0});
  }

  void CheckAreas() {
    std::vector<double> sums(input_.size(), 0.0);
    for (int k = 0; k < ComponentCount(); ++k) {
      if (info_[k].usable) sums[components_[k].source] += info_[k].area;
    }
    const AreaCorrections corrections = RoundingCorrections();
    for (size_t s = 0; s < input_.size(); ++s) {
      auto matches = [&](double expected) {
        return std::abs(sums[s] - expected) <=
               kRelative * std::abs(expected) + corrections.noise[s];
      };
      // The slivers excuse rounding; they never fail components that tile the input's area as
      // it is (a cut's point within noise of an input edge may be credited a sliver the
      // components do not miss: see RoundingCorrections()).
      const double expected = inputs_[s].area + corrections.slivers[s];
      if (!matches(expected) && !matches(inputs_[s].area)) {
        problems_.Add("area of components " + Num(sums[s]) + " != input area " + Num(expected) +
                      " (polygon " + std::to_string(s) + ")");
      }
    }
  }

  // --- Concavity within tolerance. ---

  void CheckConcavity() {
    const double tau = d_.tau;
    for (int k = 0; k < ComponentCount(); ++k) {
      if (!info_[k].valid) continue;
      const Polygon2d& polygon = components_[k].polygon;
      const Ring2d& outer = polygon.outer;
      const int n = static_cast<int>(outer.size());
      int notches = 0, first_notch = -1;
      for (int i = 0; i < n; ++i) {
        if (IsNotch(outer[(i + n - 1) % n], outer[i], outer[(i + 1) % n])) {
          if (notches++ == 0) first_notch = i;
        }
      }
      if (d_.min_convexity > 0.0) {
        const double convexity = info_[k].area / HullArea(outer, HullIndices(outer));
        if (convexity >= d_.min_convexity - kRelative) continue;
        if (notches == 0 && polygon.holes.empty()) continue;
        problems_.Add(Label(k) + "convexity " + Num(convexity) + " < min_convexity " +
                      Num(d_.min_convexity) + " with " + std::to_string(notches) + " notches and " +
                      std::to_string(polygon.holes.size()) + " holes");
        continue;
      }
      double value = 0.0;
      try {
        value = MeasureConcavity(polygon, {d_.measure, HoleDiameter::kAuto, tau}).value;
      } catch (const std::exception& error) {
        problems_.Add(Label(k) + "MeasureConcavity() failed: " + error.what());
        continue;
      }
      const double scale = inputs_[components_[k].source].scale;
      if (!(value <= tau * (1.0 + kRelative) + kHullNoise * scale)) {
        problems_.Add(Label(k) + "concavity " + Num(value) + " > tau " + Num(tau) + " (" +
                      ToString(d_.measure) + ")");
      }
      if (tau == 0.0) {
        if (notches > 0) {
          problems_.Add(Label(k) + "not convex: vertex " + std::to_string(first_notch) + " " +
                        Pt(outer[first_notch]) + " is a notch (" + std::to_string(notches) +
                        " notches, concavity " + Num(value) + ", tau 0)");
        }
        if (!polygon.holes.empty()) {
          problems_.Add(Label(k) + "not convex: " + std::to_string(polygon.holes.size()) +
                        " holes left (concavity " + Num(value) + ", tau 0)");
        }
      }
    }
  }

  // --- Openings on both boundaries. ---

  void CheckOpenings() {
    const int count = ComponentCount();
    for (size_t o = 0; o < d_.openings.size(); ++o) {
      const Opening2d& opening = d_.openings[o];
      const std::string label = "opening " + std::to_string(o) + ": ";
      bool indices_ok = true;
      for (int k : {opening.component_a, opening.component_b}) {
        if (k < 0 || k >= count) {
          problems_.Add(label + "component index " + std::to_string(k) + " out of range (" +
                        std::to_string(count) + " components)");
          indices_ok = false;
        }
      }
      if (indices_ok && opening.component_a == opening.component_b) {
        problems_.Add(label + "both sides are component " + std::to_string(opening.component_a));
        indices_ok = false;
      }
      if (opening.a == opening.b)
        problems_.Add(label + "end points a and b are equal " + Pt(opening.a));
      if (!indices_ok) continue;
      for (int k : {opening.component_a, opening.component_b}) {
        if (!info_[k].usable) continue;
        const RingLocator& locator = *info_[k].locator;
        for (const auto& [name, p] :
             {std::make_pair("a", opening.a), std::make_pair("b", opening.b)}) {
          if (locator.NearBoundary(p, info_[k].tolerance)) continue;
          problems_.Add(label + "end point " + name + " " + Pt(p) +
                        " is not on the boundary of component " + std::to_string(k) +
                        " (distance " + Num(locator.BoundaryDistance(p)) + ")");
        }
      }
    }
  }

  // --- Summary figures. ---

  void CheckStats() {
    const DecompositionStats2d& stats = d_.stats;
    if (stats.components != ComponentCount()) {
      problems_.Add("stats.components " + std::to_string(stats.components) +
                    " != " + std::to_string(ComponentCount()) + " components");
    }
    double max_concavity = 0.0, areas = 0.0, hull_areas = 0.0;
    for (const Component2d& c : components_) {
      max_concavity = std::max(max_concavity, c.concavity);
      areas += Area(c.polygon);
      hull_areas += SignedArea(c.hull);
    }
    if (!(std::abs(stats.max_concavity - max_concavity) <=
          kRelative * std::max(std::abs(stats.max_concavity), std::abs(max_concavity)))) {
      problems_.Add("stats.max_concavity " + Num(stats.max_concavity) +
                    " != largest component concavity " + Num(max_concavity));
    }
    if (!components_.empty() && hull_areas > 0.0) {
      const double convexity = areas / hull_areas;  // Eqn. 4.4.
      if (!(std::abs(stats.convexity - convexity) <= kRelative)) {
        problems_.Add("stats.convexity " + Num(stats.convexity) +
                      " != sum of areas / sum of hull areas " + Num(convexity) + " (Eqn. 4.4)");
      }
    }
  }

  const std::vector<Polygon2d>& input_;
  const Decomposition2d& d_;
  const std::vector<Component2d>& components_;
  std::vector<InputInfo> inputs_;
  std::vector<ComponentInfo> info_;
  std::vector<EdgeRef> edges_;
  std::map<int, std::pair<SelfKey, std::string>> self_;
  std::map<std::pair<int, int>, Point2d> overlaps_;
  std::map<int, std::pair<std::tuple<int, double, double>, std::string>> leaves_;
  ProblemList problems_;
};

}  // namespace

DecompositionCheck CheckDecomposition(const std::vector<Polygon2d>& input,
                                      const Decomposition2d& decomposition) {
  DecompositionCheck check;
  check.problems = Checker(input, decomposition).Run();
  return check;
}

}  // namespace acdplan::acd
