#include "acd/internal/even_odd_regions.h"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_with_history_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "acd/internal/disjoint_sets.h"
#include "acd/internal/exact_rounding.h"

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

// `loop` split where it passes a vertex again into loops that pass each vertex once: a face's
// boundary that touches itself at a point (a hole touching the outline there) is two rings.
std::vector<ExactRing> SplitAtRepeats(const ExactRing& loop) {
  std::vector<ExactRing> rings;
  ExactRing stack;
  std::map<ExactPoint, size_t> at;  // Where each vertex on the stack is.
  for (const ExactPoint& p : loop) {
    const auto seen = at.find(p);
    if (seen == at.end()) {
      at.emplace(p, stack.size());
      stack.push_back(p);
      continue;
    }
    // The stretch since p's first visit is a ring of its own; p stays for the rest.
    const size_t first = seen->second;
    for (size_t k = first + 1; k < stack.size(); ++k) at.erase(stack[k]);
    rings.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end());
    stack.resize(first + 1);
  }
  rings.push_back(std::move(stack));
  return rings;
}

// Whether a Tidy() ring (it visits each vertex once, SplitAtRepeats()) runs counter-clockwise:
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

}  // namespace

std::vector<Polygon2d> EvenOddRegions(const std::vector<std::vector<Ring2d>>& layers) {
  if (layers.size() > 32) throw std::invalid_argument("EvenOddRegions(): more than 32 layers");
  if (layers.empty()) return {};
  // Layer by layer, so that the curves new after each insertion are that layer's.
  Arrangement arrangement;
  std::unordered_map<const Traits::Curve_2*, unsigned> layer_bit;
  for (size_t layer = 0; layer < layers.size(); ++layer) {
    std::vector<Traits::Curve_2> segments;
    for (const Ring2d& ring : layers[layer]) {
      for (size_t i = 0; i < ring.size(); ++i) {
        const Point2d& a = ring[i];
        const Point2d& b = ring[i + 1 == ring.size() ? 0 : i + 1];
        if (a != b) segments.emplace_back(ExactPoint(a.x(), a.y()), ExactPoint(b.x(), b.y()));
      }
    }
    CGAL::insert(arrangement, segments.begin(), segments.end());
    for (auto c = arrangement.curves_begin(); c != arrangement.curves_end(); ++c) {
      const Traits::Curve_2* curve = &*c;
      layer_bit.emplace(curve, 1u << layer);  // Keeps the layer of curves inserted before.
    }
  }
  // The layers whose parity flips across an edge.
  auto flips = [&](const Halfedge& h) {
    const Arrangement::Halfedge_handle e = arrangement.non_const_handle(h);
    unsigned mask = 0;
    for (auto c = arrangement.originating_curves_begin(e);
         c != arrangement.originating_curves_end(e); ++c) {
      const Traits::Curve_2* curve = &*c;
      mask ^= layer_bit.at(curve);
    }
    return mask;
  };

  // Each face's parities, walking out from the unbounded face (all even).
  std::unordered_map<const void*, int> index_of;  // Face -> index, in the arrangement's order.
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    index_of.emplace(&*f, static_cast<int>(index_of.size()));
  }
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
    if (outlines != 1) throw std::logic_error("EvenOddRegions(): a part with no or two outlines");
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

}  // namespace acdplan::acd::internal
