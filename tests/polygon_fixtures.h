#pragma once
// Small polygon helpers shared by the acd and envs tests.

#include <vector>

#include "acd/polygon2d.h"
#include "base/random.h"

namespace acdplan::test {

/// The counter-clockwise square [x0, x0 + size] x [y0, y0 + size].
inline acd::Ring2d SquareRing(double x0, double y0, double size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

/// The summed area of `polygons` (each outer ring minus its holes).
inline double TotalArea(const std::vector<acd::Polygon2d>& polygons) {
  double area = 0.0;
  for (const acd::Polygon2d& p : polygons) area += acd::Area(p);
  return area;
}

/// Rings of random points for the spatial-index tests (not simple: the indexes do not care), on
/// `side` x `side` steps of `step` from `origin`: plain, with a few far-flung vertices (long
/// edges, which coarsen a grid), or clustered in a corner (many points per cell). `lattice`
/// puts the points on the integer lattice of steps, so that distances tie.
inline acd::Polygon2d RandomRings(RandomEngine& rng, const acd::Point2d& origin, double step,
                                  bool lattice) {
  const int side = 2 + static_cast<int>(UniformIndex(rng, 30));
  const int kind = static_cast<int>(UniformIndex(rng, 3));
  auto coordinate = [&]() {
    return lattice ? static_cast<double>(UniformIndex(rng, side)) : UniformReal(rng, 0.0, side);
  };
  auto point = [&]() {
    const double x = coordinate();
    acd::Point2d q(x, coordinate());
    if (kind == 1 && UniformIndex(rng, 10) == 0) q *= 40.0;  // far out
    if (kind == 2 && UniformIndex(rng, 4) != 0) q *= 0.01;   // clustered
    return acd::Point2d(origin + step * q);
  };
  acd::Polygon2d polygon;
  const int n = 1 + static_cast<int>(UniformIndex(rng, 80));
  for (int i = 0; i < n; ++i) polygon.outer.push_back(point());
  const int holes = static_cast<int>(UniformIndex(rng, 6));
  for (int k = 0; k < holes; ++k) {
    polygon.holes.emplace_back();
    const int m = 1 + static_cast<int>(UniformIndex(rng, 40));
    for (int i = 0; i < m; ++i) polygon.holes.back().push_back(point());
  }
  return polygon;
}

}  // namespace acdplan::test
