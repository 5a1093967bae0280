#include "envs/free_space2d.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "acd/internal/split_at_repeats.h"
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
using Loop = std::vector<Point>;
using internal::ToDouble;

struct PointLess {
  bool operator()(const Point& a, const Point& b) const {
    return CGAL::compare_xy(a, b) == CGAL::SMALLER;
  }
};

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

CGAL::Sign AreaSign(const Loop& loop) {
  return CGAL::sign(CGAL::polygon_area_2(loop.begin(), loop.end(), Kernel()));
}

// One region of CGAL's output split into simple loops: counter-clockwise loops bound free
// lobes, clockwise loops bound holes (the free side is on the left of every loop).
struct SplitRegion {
  std::vector<Loop> outers, holes;
};

SplitRegion Split(const PolygonWithHoles& region) {
  SplitRegion split;
  auto add = [&split](const Polygon& ring) {
    for (Loop& loop : acd::internal::SplitAtRepeats<Point, PointLess>(
             Loop(ring.vertices_begin(), ring.vertices_end()))) {
      const CGAL::Sign sign = AreaSign(loop);
      if (sign == CGAL::POSITIVE) split.outers.push_back(std::move(loop));
      if (sign == CGAL::NEGATIVE) split.holes.push_back(std::move(loop));
    }
  };
  add(region.outer_boundary());
  for (auto hole = region.holes_begin(); hole != region.holes_end(); ++hole) add(*hole);
  return split;
}

// Vertices where a hole loop meets another loop of the same region: no set of simple,
// disjoint rings describes the region there.
std::vector<Point> HolePinches(const SplitRegion& split) {
  std::map<Point, int, PointLess> uses;
  for (const auto* loops : {&split.outers, &split.holes}) {
    for (const Loop& loop : *loops) {
      for (const Point& p : loop) ++uses[p];
    }
  }
  std::vector<Point> pinches;
  for (const Loop& hole : split.holes) {
    for (const Point& p : hole) {
      if (uses[p] >= 2) pinches.push_back(p);
    }
  }
  return pinches;
}

// The free space of `prepared` by exact Boolean operations, pinches closed by diamonds of
// half-diagonal `gap` and lobes split (FreeSpace2d()), unsorted and not yet prepared.
std::vector<acd::Polygon2d> BooleanFreeSpace(const Workspace2d& prepared, double gap) {
  std::vector<PolygonWithHoles> obstacles;
  obstacles.reserve(prepared.obstacles.size());
  for (const acd::Polygon2d& obstacle : prepared.obstacles) obstacles.push_back(ToCgal(obstacle));
  PolygonSet blocked;
  if (!obstacles.empty()) blocked.join(obstacles.begin(), obstacles.end());
  PolygonSet free(ToCgal(BoundsPolygon(prepared.bounds).outer));
  free.difference(blocked);

  // Close hole pinches with small diamonds of obstacle, region by region (a region without
  // hole pinches is final; the overlay stays as small as the region), then split the remaining
  // (lobe) pinches. One round removes every hole pinch; further rounds are a safety net.
  std::vector<SplitRegion> regions;
  std::vector<PolygonWithHoles> work;
  free.polygons_with_holes(std::back_inserter(work));
  for (int round = 0; !work.empty(); ++round) {
    if (round == 3) throw std::logic_error("FreeSpace2d(): pinches remain after 3 rounds");
    std::vector<PolygonWithHoles> next;
    for (const PolygonWithHoles& part : work) {
      SplitRegion split = Split(part);
      std::vector<Point> pinches = HolePinches(split);
      if (pinches.empty()) {
        regions.push_back(std::move(split));
        continue;
      }
      std::sort(pinches.begin(), pinches.end(), PointLess());
      pinches.erase(std::unique(pinches.begin(), pinches.end()), pinches.end());
      std::vector<Polygon> diamonds;
      const Kernel::FT e(gap);
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
      PolygonSet region(part);
      region.difference(closing);
      region.polygons_with_holes(std::back_inserter(next));
    }
    work = std::move(next);
  }

  std::vector<acd::Polygon2d> result;
  for (const SplitRegion& region : regions) {
    std::vector<acd::Polygon2d> lobes;
    for (const Loop& outer : region.outers) lobes.push_back({ToDouble(outer), {}});
    for (const Loop& hole : region.holes) {
      size_t owner = 0;
      if (region.outers.size() > 1) {
        // No hole vertex is on another loop now, so any vertex decides.
        while (owner < region.outers.size() &&
               CGAL::bounded_side_2(region.outers[owner].begin(), region.outers[owner].end(),
                                    hole.front(), Kernel()) != CGAL::ON_BOUNDED_SIDE) {
          ++owner;
        }
        if (owner == region.outers.size()) {
          throw std::logic_error("FreeSpace2d(): a hole lies in no outer loop");
        }
      }
      lobes[owner].holes.push_back(ToDouble(hole));
    }
    for (acd::Polygon2d& lobe : lobes) result.push_back(std::move(lobe));
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
  std::optional<std::vector<acd::Polygon2d>> traced = internal::RectilinearFreeSpace(prepared, gap);
  std::vector<acd::Polygon2d> result =
      traced ? std::move(*traced) : BooleanFreeSpace(prepared, gap);
  auto lowest_left = [](const acd::Polygon2d& polygon) {
    acd::Point2d best = polygon.outer.front();
    for (const acd::Point2d& p : polygon.outer) {
      if (p.x() < best.x() || (p.x() == best.x() && p.y() < best.y())) best = p;
    }
    return best;
  };
  std::sort(result.begin(), result.end(), [&](const acd::Polygon2d& a, const acd::Polygon2d& b) {
    const acd::Point2d pa = lowest_left(a), pb = lowest_left(b);
    return pa.x() < pb.x() || (pa.x() == pb.x() && pa.y() < pb.y());
  });
  // The trace's polygons are valid by construction (rings along cell sides, corners cut by less
  // than a quarter of the spacing) and clean (vertices only where the boundary turns): checked
  // again, they took three quarters of the free-space time of a large map. The Boolean
  // construction's are rounded from exact points, so they are checked.
  if (traced) return result;
  for (size_t k = 0; k < result.size(); ++k) {
    result[k] =
        acd::PreparePolygon(result[k], "FreeSpace2d(): free space polygon " + std::to_string(k));
  }
  return result;
}

}  // namespace acdplan::envs
