#include "acd/internal/even_odd_regions.h"

#include <CGAL/Arr_batched_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_with_history_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "acd/internal/disjoint_sets.h"
#include "acd/internal/exact_rounding.h"
#include "acd/internal/split_at_repeats.h"

namespace acdplan::acd::internal {
namespace {

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Exact::Point_2;
using Traits = CGAL::Arr_segment_traits_2<Exact>;
using Arrangement = CGAL::Arrangement_with_history_2<Traits>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;
using ExactRing = std::vector<ExactPoint>;

// `ring` (interior on its left) without the vertices between two collinear edges, started at its
// lowest vertex. Dropping such a vertex leaves its neighbours' edge directions as they were, so
// one pass against the original neighbours finds them all. A boundary never doubles back on
// itself (that edge would have the region on both sides), so a collinear vertex lies between.
ExactRing Tidy(const ExactRing& ring) {
  const size_t n = ring.size();
  ExactRing kept;
  for (size_t i = 0; i < n; ++i) {
    const ExactPoint& before = ring[i == 0 ? n - 1 : i - 1];
    const ExactPoint& after = ring[i + 1 == n ? 0 : i + 1];
    if (!CGAL::collinear(before, ring[i], after)) kept.push_back(ring[i]);
  }
  std::rotate(kept.begin(), std::min_element(kept.begin(), kept.end()), kept.end());
  return kept;
}

// Whether a Tidy() ring (it visits each vertex once: SplitAtRepeats()) runs counter-clockwise:
// its turn at its lowest vertex, where a simple ring is convex, is to the left. It is never
// straight: both neighbours come after that vertex, so a straight turn would double back.
bool CounterClockwise(const ExactRing& ring) {
  return CGAL::orientation(ring.back(), ring.front(), ring[1]) == CGAL::LEFT_TURN;
}

Ring2d Rounded(const ExactRing& ring) {
  Ring2d out;
  out.reserve(ring.size());
  for (const ExactPoint& p : ring) out.push_back(RoundToDouble(p));
  return out;
}

// Each face of `arrangement` -> its index, in the arrangement's order.
std::unordered_map<const void*, int> FaceIndices(const Arrangement& arrangement) {
  std::unordered_map<const void*, int> index_of;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    index_of.emplace(&*f, static_cast<int>(index_of.size()));
  }
  return index_of;
}

// The union of the faces of `arrangement` for which `inside` holds, as polygons with holes
// (see EvenOddRegions() for the conventions). `index_of`: each face's index.
template <class Inside>
std::vector<Polygon2d> RegionsOf(const Arrangement& arrangement,
                                 const std::unordered_map<const void*, int>& index_of,
                                 const Inside& inside) {
  auto index = [&](const Face& f) { return index_of.at(&*f); };
  auto on_boundary = [&](const Halfedge& h) {
    return inside(h->face()) && !inside(h->twin()->face());
  };

  // Polygons: inside faces joined across edges with the region on both sides.
  DisjointSets parts(static_cast<int>(index_of.size()));
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    if (inside(e->face()) && inside(e->twin()->face())) {
      parts.Unite(index(e->face()), index(e->twin()->face()));
    }
  }
  // Boundary loops, interior on the left; at a vertex, turn to the next boundary edge around it
  // inside the region, so that loops of parts meeting at a point separate.
  std::unordered_map<int, std::vector<ExactRing>> loops_of;  // By part.
  std::unordered_map<const void*, char> used;
  for (auto h = arrangement.halfedges_begin(); h != arrangement.halfedges_end(); ++h) {
    if (!on_boundary(h) || used[&*h]) continue;
    ExactRing loop;
    Halfedge e = h;
    do {
      used[&*e] = 1;
      loop.push_back(e->source()->point());
      Halfedge next = e->next();
      while (!on_boundary(next)) next = next->twin()->next();
      e = next;
    } while (e != Halfedge(h));
    const int part = parts.Find(index(h->face()));
    // A face's boundary that touches itself (a hole touching the outline) is several rings.
    for (const ExactRing& ring : SplitAtRepeats(loop)) loops_of[part].push_back(Tidy(ring));
  }

  // Per part: the outer ring is its one counter-clockwise loop (holes run clockwise); rings in
  // lexicographic order of their vertices, each started at its lowest.
  auto before = [](const ExactRing& a, const ExactRing& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  };
  struct Part {
    ExactRing outer;
    std::vector<ExactRing> holes;
  };
  std::vector<Part> found;
  for (auto& entry : loops_of) {  // In any order: sorted below.
    std::vector<ExactRing>& loops = entry.second;
    std::sort(loops.begin(), loops.end(), before);
    Part p;
    int outlines = 0;
    for (ExactRing& ring : loops) {
      if (CounterClockwise(ring)) {
        p.outer = std::move(ring);
        ++outlines;
      } else {
        p.holes.push_back(std::move(ring));
      }
    }
    // A part is connected: one outline, whatever touches it.
    if (outlines != 1) throw std::logic_error("RegionsOf(): a part with no or two outlines");
    found.push_back(std::move(p));
  }
  std::sort(found.begin(), found.end(),
            [&](const Part& a, const Part& b) { return before(a.outer, b.outer); });
  std::vector<Polygon2d> regions;
  for (const Part& part : found) {
    Polygon2d polygon{Rounded(part.outer), {}};
    for (const ExactRing& hole : part.holes) polygon.holes.push_back(Rounded(hole));
    regions.push_back(std::move(polygon));
  }
  return regions;
}

}  // namespace

std::vector<Polygon2d> EvenOddRegions(const std::vector<std::vector<Ring2d>>& layers) {
  if (layers.size() > 32) throw std::invalid_argument("EvenOddRegions(): more than 32 layers");
  if (layers.empty()) return {};
  // Every edge once, ends in lexicographic order, with the layers whose parity it flips: those
  // that list it an odd number of times (either way round). So the edges that two triangles of
  // a triangulation share vanish, and an edge of several layers' outlines (two sides of a cut
  // usually cover the same polygon) is one segment: the arrangement holds the outlines, once.
  using Edge = std::array<double, 4>;
  std::vector<std::pair<Edge, unsigned>> listed;
  for (size_t layer = 0; layer < layers.size(); ++layer) {
    for (const Ring2d& ring : layers[layer]) {
      for (size_t i = 0; i < ring.size(); ++i) {
        const Point2d& a = ring[i];
        const Point2d& b = ring[i + 1 == ring.size() ? 0 : i + 1];
        if (a == b) continue;
        const bool forward = a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
        const Point2d& p = forward ? a : b;
        const Point2d& q = forward ? b : a;
        listed.push_back({{p.x(), p.y(), q.x(), q.y()}, 1u << layer});
      }
    }
  }
  std::sort(listed.begin(), listed.end());
  std::vector<Traits::Curve_2> segments;
  std::vector<unsigned> flips_of;  // Per segment.
  for (size_t first = 0, last = 0; first < listed.size(); first = last) {
    unsigned mask = 0;
    for (; last < listed.size() && listed[last].first == listed[first].first; ++last) {
      mask ^= listed[last].second;
    }
    if (mask == 0) continue;
    const Edge& e = listed[first].first;
    segments.emplace_back(ExactPoint(e[0], e[1]), ExactPoint(e[2], e[3]));
    flips_of.push_back(mask);
  }
  // The arrangement keeps its curves in insertion order, which ties each to its mask; checked,
  // as CGAL does not document the order.
  Arrangement arrangement;
  CGAL::insert(arrangement, segments.begin(), segments.end());
  std::unordered_map<const Traits::Curve_2*, unsigned> curve_flips;
  size_t k = 0;
  for (auto c = arrangement.curves_begin(); c != arrangement.curves_end(); ++c, ++k) {
    if (k >= segments.size() || c->source() != segments[k].source() ||
        c->target() != segments[k].target()) {
      throw std::logic_error("EvenOddRegions(): the arrangement reordered its curves");
    }
    const Traits::Curve_2* curve = &*c;
    curve_flips.emplace(curve, flips_of[k]);
  }
  // The layers whose parity flips across an edge.
  auto flips = [&](const Halfedge& h) {
    const Arrangement::Halfedge_handle e = arrangement.non_const_handle(h);
    unsigned mask = 0;
    for (auto c = arrangement.originating_curves_begin(e);
         c != arrangement.originating_curves_end(e); ++c) {
      const Traits::Curve_2* curve = &*c;
      mask ^= curve_flips.at(curve);
    }
    return mask;
  };

  // Each face's parities, walking out from the unbounded face (all even).
  const std::unordered_map<const void*, int> index_of = FaceIndices(arrangement);
  auto index = [&](const Face& f) { return index_of.at(&*f); };
  constexpr unsigned kUnknown = ~0u;
  std::vector<unsigned> parity(index_of.size(), kUnknown);
  std::vector<Face> stack{arrangement.unbounded_face()};
  parity[static_cast<size_t>(index(stack.back()))] = 0;
  auto visit_ccb = [&](Arrangement::Ccb_halfedge_const_circulator ccb, unsigned p) {
    auto h = ccb;
    do {
      const Face other = h->twin()->face();
      unsigned& q = parity[static_cast<size_t>(index(other))];
      if (q == kUnknown) {
        q = p ^ flips(h);
        stack.push_back(other);
      }
    } while (++h != ccb);
  };
  while (!stack.empty()) {
    const Face f = stack.back();
    stack.pop_back();
    const unsigned p = parity[static_cast<size_t>(index(f))];
    if (!f->is_unbounded()) visit_ccb(f->outer_ccb(), p);
    for (auto inner = f->inner_ccbs_begin(); inner != f->inner_ccbs_end(); ++inner) {
      visit_ccb(*inner, p);
    }
  }
  const unsigned all = layers.size() == 32 ? ~0u : (1u << layers.size()) - 1;
  auto inside = [&](const Face& f) { return parity[static_cast<size_t>(index(f))] == all; };

  return RegionsOf(arrangement, index_of, inside);
}

BoundedRegions RegionsOfSegmentGraph(const std::vector<std::pair<Point2d, Point2d>>& segments,
                                     const std::vector<Point2d>& hole_points) {
  std::vector<Traits::Curve_2> curves;
  for (const auto& [a, b] : segments) {
    if (a != b) curves.emplace_back(ExactPoint(a.x(), a.y()), ExactPoint(b.x(), b.y()));
  }
  Arrangement arrangement;
  CGAL::insert(arrangement, curves.begin(), curves.end());
  const std::unordered_map<const void*, int> index_of = FaceIndices(arrangement);
  std::vector<char> emptied(index_of.size(), 0);
  BoundedRegions result;
  // The faces that hold hole points, found in one sweep; the sweep reports the points in its
  // own order, so each is matched to the holes at its place.
  std::map<ExactPoint, std::vector<int>> holes_at;
  for (size_t k = 0; k < hole_points.size(); ++k) {
    holes_at[ExactPoint(hole_points[k].x(), hole_points[k].y())].push_back(static_cast<int>(k));
  }
  std::vector<ExactPoint> queries;
  for (const auto& entry : holes_at) queries.push_back(entry.first);
  using Location = CGAL::Arr_point_location_result<Arrangement>::Type;
  std::vector<std::pair<ExactPoint, Location>> located;
  CGAL::locate(arrangement, queries.begin(), queries.end(), std::back_inserter(located));
  for (const auto& [point, location] : located) {
    const int first = holes_at.at(point).front();
    if (const Face* face = boost::get<Face>(&location)) {
      emptied[static_cast<size_t>(index_of.at(&**face))] = 1;
    } else if (result.hole_on_segment < 0 || first < result.hole_on_segment) {
      result.hole_on_segment = first;
    }
  }
  auto inside = [&](const Face& f) {
    return !f->is_unbounded() && !emptied[static_cast<size_t>(index_of.at(&*f))];
  };
  result.polygons = RegionsOf(arrangement, index_of, inside);
  return result;
}

}  // namespace acdplan::acd::internal
