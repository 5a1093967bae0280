#include "envs/free_space2d.h"

#include <CGAL/Boolean_set_operations_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "acd/prepare_polygon.h"
#include "base/input_error.h"
#include "envs/internal/exact_polygons.h"
#include "envs/internal/rectilinear_free_space.h"

namespace acdplan::envs {
namespace {

using Kernel = internal::ExactKernel;
using Point = internal::ExactPoint;
using Polygon = internal::ExactPolygon;
using PolygonWithHoles = internal::ExactPolygonWithHoles;
using PolygonSet = internal::ExactPolygonSet;
using internal::ToDouble;

Polygon ToCgal(const acd::Ring2d& ring) {
  Polygon polygon;
  for (const acd::Point2d& p : ring) polygon.push_back(Point(p.x(), p.y()));
  return polygon;
}

PolygonWithHoles ToCgal(const acd::Polygon2d& polygon) {
  PolygonWithHoles result(ToCgal(polygon.outer));
  for (const acd::Ring2d& hole : polygon.holes) result.add_hole(ToCgal(hole));
  return result;
}

// The vertices of `free`'s arrangement where one free face lies in two of the wedges around the
// vertex: the face touches itself there (a hole touching the outer ring or another hole at a
// point), which no set of simple, disjoint rings describes. Two faces meeting at a vertex are
// no pinch: they are two polygons.
std::vector<Point> SelfTouches(const PolygonSet& free) {
  std::vector<Point> pinches;
  std::vector<const void*> faces;
  const PolygonSet::Arrangement_2& arrangement = free.arrangement();
  for (auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v) {
    if (v->degree() < 4) continue;  // Two free wedges need four edges.
    faces.clear();
    auto halfedge = v->incident_halfedges();  // Each into v, its left face one wedge.
    const auto first = halfedge;
    do {
      if (halfedge->face()->contained()) faces.push_back(&*halfedge->face());
    } while (++halfedge != first);
    std::sort(faces.begin(), faces.end());
    if (std::adjacent_find(faces.begin(), faces.end()) != faces.end()) {
      pinches.push_back(v->point());
    }
  }
  return pinches;
}

// The free space of `prepared` by exact Boolean operations, each point where a region touches
// itself closed by a diamond of half-diagonal `gap`: one polygon per region, checked by
// acd::PreparePolygon(), unsorted.
std::vector<acd::Polygon2d> BooleanFreeSpace(const Workspace2d& prepared, double gap) {
  std::vector<PolygonWithHoles> obstacles;
  obstacles.reserve(prepared.obstacles.size());
  for (const acd::Polygon2d& obstacle : prepared.obstacles) obstacles.push_back(ToCgal(obstacle));
  PolygonSet blocked;
  if (!obstacles.empty()) blocked.join(obstacles.begin(), obstacles.end());
  PolygonSet free(ToCgal(BoundsPolygon(prepared.bounds).outer));
  free.difference(blocked);

  // A diamond lies in the wedges of one point, far from any other vertex, so it makes no new
  // self-touch: one round closes them all, a second only checks.
  const Kernel::FT e(gap);
  for (int round = 0;; ++round) {
    const std::vector<Point> pinches = SelfTouches(free);
    if (pinches.empty()) break;
    if (round == 2) throw std::logic_error("FreeSpace2d(): pinches remain after 2 rounds");
    std::vector<Polygon> diamonds;
    for (const Point& p : pinches) {
      Polygon diamond;
      diamond.push_back(Point(p.x() + e, p.y()));
      diamond.push_back(Point(p.x(), p.y() + e));
      diamond.push_back(Point(p.x() - e, p.y()));
      diamond.push_back(Point(p.x(), p.y() - e));
      diamonds.push_back(std::move(diamond));
    }
    PolygonSet closing;
    closing.join(diamonds.begin(), diamonds.end());
    free.difference(closing);
  }

  // One polygon per free face of the arrangement, the regions themselves (CGAL's own output
  // rings can join two regions that meet at points into one ring, with an obstacle between them
  // as a hole touching it). With the self-touches closed, a face's boundary cycles are simple
  // and disjoint.
  auto ring = [](PolygonSet::Arrangement_2::Ccb_halfedge_const_circulator first) {
    std::vector<Point> points;
    auto halfedge = first;
    do {
      points.push_back(halfedge->target()->point());
    } while (++halfedge != first);
    return ToDouble(points);
  };
  std::vector<acd::Polygon2d> result;
  const PolygonSet::Arrangement_2& arrangement = free.arrangement();
  for (auto face = arrangement.faces_begin(); face != arrangement.faces_end(); ++face) {
    if (!face->contained() || face->is_unbounded()) continue;
    acd::Polygon2d region{ring(face->outer_ccb()), {}};
    for (auto hole = face->inner_ccbs_begin(); hole != face->inner_ccbs_end(); ++hole) {
      region.holes.push_back(ring(*hole));
    }
    result.push_back(acd::PreparePolygon(
        region, "FreeSpace2d(): free space region " + std::to_string(result.size())));
  }
  return result;
}

}  // namespace

std::vector<acd::Polygon2d> FreeSpace2d(const Workspace2d& workspace,
                                        const FreeSpace2dOptions& options) {
  const Workspace2d prepared = PrepareWorkspace2d(workspace, "FreeSpace2d()");
  if (!std::isfinite(options.pinch_gap) || !(options.pinch_gap > 0.0)) {
    throw InputError("FreeSpace2d(): pinch_gap must be finite and > 0, got " +
                     std::to_string(options.pinch_gap));
  }
  const double gap = options.pinch_gap * prepared.bounds.diagonal().norm();
  // The trace's polygons are valid by construction (rings along cell sides, corners cut by less
  // than a quarter of the spacing) and clean (vertices only where the boundary turns), so they
  // skip the check, which took three quarters of the free-space time of a large map; the
  // Boolean construction's are rounded from exact points and checked.
  std::optional<std::vector<acd::Polygon2d>> traced = internal::RectilinearFreeSpace(prepared, gap);
  std::vector<acd::Polygon2d> result =
      traced ? std::move(*traced) : BooleanFreeSpace(prepared, gap);
  auto before = [](const acd::Point2d& p, const acd::Point2d& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  };
  auto lowest_left = [&](const acd::Polygon2d& polygon) {
    return *std::min_element(polygon.outer.begin(), polygon.outer.end(), before);
  };
  std::sort(result.begin(), result.end(), [&](const acd::Polygon2d& a, const acd::Polygon2d& b) {
    const acd::Point2d pa = lowest_left(a), pb = lowest_left(b);
    if (pa != pb) return before(pa, pb);
    // Two regions whose lowest-left corner is one point (slanted obstacles can wedge them so):
    // by their rings, so that their order is not the sort's choice.
    return std::lexicographical_compare(a.outer.begin(), a.outer.end(), b.outer.begin(),
                                        b.outer.end(), before);
  });
  return result;
}

}  // namespace acdplan::envs
