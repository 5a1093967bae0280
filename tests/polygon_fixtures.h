#pragma once
// Small polygon helpers shared by the acd and envs tests.

#include <vector>

#include "acd/polygon2d.h"

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

}  // namespace acdplan::test
