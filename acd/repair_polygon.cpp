#include "acd/repair_polygon.h"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_with_history_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "acd/internal/exact_rounding.h"
#include "acd/internal/text_parsing.h"
#include "acd/prepare_polygon.h"
#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Arr_segment_traits_2<Exact>;
using Arrangement = CGAL::Arrangement_with_history_2<Traits>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;

std::string RingName(size_t ring) {
  return ring == 0 ? "outer ring" : "hole " + std::to_string(ring - 1);
}

// Distinct vertices of `ring` and whether they span an area (not all collinear), exactly.
int DistinctNonCollinear(const Ring2d& ring, bool* spans_area) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Epick::Point_2> points;
  for (const Point2d& p : ring) points.emplace_back(p.x(), p.y());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  *spans_area = false;
  for (size_t i = 2; i < points.size() && !*spans_area; ++i) {
    *spans_area = !CGAL::collinear(points[0], points[1], points[i]);
  }
  return static_cast<int>(points.size());
}

// The message of `error` without the "<where>: " it starts with.
std::string Rule(const InputError& error, const std::string& where) {
  std::string message = error.what();
  if (message.compare(0, where.size() + 2, where + ": ") == 0) message.erase(0, where.size() + 2);
  return message;
}

Point2d ToDouble(const Exact::Point_2& p) { return internal::RoundToDouble(p); }

}  // namespace

RepairedPolygon RepairPolygon(const Polygon2d& raw, const std::string& where) {
  RepairedPolygon result;
  std::string rule;
  try {
    result.polygons = PreparePolygons(raw, where);
    return result;
  } catch (const InputError& error) {
    rule = Rule(error, where);
  }
  const size_t ring_count = 1 + raw.holes.size();
  auto ring_at = [&](size_t r) -> const Ring2d& { return r == 0 ? raw.outer : raw.holes[r - 1]; };
  for (size_t r = 0; r < ring_count; ++r) {
    for (const Point2d& p : ring_at(r)) {
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw InputError(where + ": " + rule);
    }
  }

  // 1. Rings that collapse.
  std::vector<size_t> kept;
  for (size_t r = 0; r < ring_count; ++r) {
    bool spans_area = false;
    const int distinct = DistinctNonCollinear(ring_at(r), &spans_area);
    if (distinct < 3 || !spans_area) {
      result.changes.push_back(where + ": repaired: " + RingName(r) + " has " +
                               std::to_string(distinct) + " distinct vertices" +
                               (distinct >= 3 ? ", all collinear" : "") + ": dropped");
    } else {
      kept.push_back(r);
    }
  }
  if (kept.empty() || kept[0] != 0) {
    result.changes.push_back(where + ": repaired: nothing remains without the outer ring");
    return result;
  }
  Polygon2d rest{raw.outer, {}};
  for (size_t k = 1; k < kept.size(); ++k) rest.holes.push_back(ring_at(kept[k]));
  if (kept.size() < ring_count) {
    try {
      result.polygons = PreparePolygons(rest, where);
      return result;
    } catch (const InputError& error) {
      rule = Rule(error, where);
    }
  }

  // 2. Even-odd rule over the exact arrangement of all ring edges.
  std::vector<Traits::X_monotone_curve_2> segments;
  for (size_t k = 0; k < kept.size(); ++k) {
    const Ring2d& ring = ring_at(kept[k]);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2d& a = ring[i];
      const Point2d& b = ring[(i + 1) % ring.size()];
      if (a == b) continue;
      segments.emplace_back(Exact::Point_2(a.x(), a.y()), Exact::Point_2(b.x(), b.y()));
    }
  }
  Arrangement arrangement;
  CGAL::insert(arrangement, segments.begin(), segments.end());
  // Parity of each face: a walk from the unbounded face, flipping across edges that an odd
  // number of ring edges cover.
  std::map<const void*, int> parity;
  auto key = [](const Face& f) { return static_cast<const void*>(&*f); };
  auto odd = [&](const Halfedge& h) {
    return arrangement.number_of_originating_curves(arrangement.non_const_handle(h)) % 2 == 1;
  };
  std::vector<Face> stack{arrangement.unbounded_face()};
  parity[key(arrangement.unbounded_face())] = 0;
  auto visit_ccb = [&](Arrangement::Ccb_halfedge_const_circulator ccb, int p) {
    auto h = ccb;
    do {
      const Face other = h->twin()->face();
      if (parity.count(key(other)) == 0) {
        parity[key(other)] = p ^ (odd(h) ? 1 : 0);
        stack.push_back(other);
      }
    } while (++h != ccb);
  };
  while (!stack.empty()) {
    const Face f = stack.back();
    stack.pop_back();
    const int p = parity[key(f)];
    if (!f->is_unbounded()) visit_ccb(f->outer_ccb(), p);
    for (auto inner = f->inner_ccbs_begin(); inner != f->inner_ccbs_end(); ++inner) {
      visit_ccb(*inner, p);
    }
  }
  auto inside = [&](const Face& f) { return parity[key(f)] == 1; };
  auto on_boundary = [&](const Halfedge& h) {
    return inside(h->face()) && !inside(h->twin()->face());
  };

  // Parts: inside faces joined across edges with inside on both sides.
  std::map<const void*, const void*> parent;
  std::function<const void*(const void*)> find = [&](const void* f) -> const void* {
    const void* p = parent.count(f) ? parent[f] : f;
    if (p == f) return f;
    return parent[f] = find(p);
  };
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    if (inside(e->face()) && inside(e->twin()->face())) {
      const void* a = find(key(e->face()));
      const void* b = find(key(e->twin()->face()));
      if (a != b) parent[a] = b;
    }
  }
  // Boundary loops, interior on the left; at a vertex, turn to the next boundary edge around it
  // inside the interior, so loops of parts meeting at a point separate.
  struct Loop {
    Ring2d ring;
    Exact::Point_2 lowest;
  };
  std::map<const void*, std::vector<Loop>> loops_of;
  std::map<const void*, char> used;
  for (auto h = arrangement.halfedges_begin(); h != arrangement.halfedges_end(); ++h) {
    if (!on_boundary(h) || used[&*h]) continue;
    Loop loop{{}, h->source()->point()};
    Halfedge e = h;
    do {
      used[&*e] = 1;
      loop.ring.push_back(ToDouble(e->source()->point()));
      if (e->source()->point() < loop.lowest) loop.lowest = e->source()->point();
      Halfedge next = e->next();
      while (!on_boundary(next)) next = next->twin()->next();
      e = next;
    } while (e != Halfedge(h));
    loops_of[find(key(h->face()))].push_back(std::move(loop));
  }
  std::vector<Polygon2d> parts;
  std::vector<Exact::Point_2> part_lowest;
  for (auto& [part, loops] : loops_of) {
    size_t outer = 0;
    for (size_t k = 1; k < loops.size(); ++k) {
      if (loops[k].lowest < loops[outer].lowest) outer = k;
    }
    Polygon2d polygon{loops[outer].ring, {}};
    for (size_t k = 0; k < loops.size(); ++k) {
      if (k != outer) polygon.holes.push_back(loops[k].ring);
    }
    parts.push_back(std::move(polygon));
    part_lowest.push_back(loops[outer].lowest);
  }
  // A deterministic order: by each part's lowest point.
  std::vector<size_t> order(parts.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return part_lowest[a] < part_lowest[b]; });
  size_t holes = 0;
  double area = 0.0;
  for (const size_t k : order) {
    std::vector<Polygon2d> prepared;
    try {
      prepared = PreparePolygons(parts[k], where);
    } catch (const InputError& error) {
      throw InputError(where + ": repair failed: rounding the even-odd result to doubles left " +
                       Rule(error, where) + " (input: " + rule + ")");
    }
    for (Polygon2d& p : prepared) {
      holes += p.holes.size();
      area += Area(p);
      result.polygons.push_back(std::move(p));
    }
  }
  result.changes.push_back(where + ": repaired: " + rule + ": rebuilt by the even-odd rule into " +
                           std::to_string(result.polygons.size()) + " polygon(s) with " +
                           std::to_string(holes) + " hole(s), area " + FormatSignificant(area, 15));
  return result;
}

}  // namespace acdplan::acd
