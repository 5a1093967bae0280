#pragma once
// The exact 2D polygons envs' booleans (free space, footprints) work in, and their rounding
// to acd's doubles. Internal: includes CGAL.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <vector>

#include "acd/internal/exact_rounding.h"
#include "acd/polygon2d.h"

namespace acdplan::envs::internal {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = ExactKernel::Point_2;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<ExactKernel>;
using ExactPolygonSet = CGAL::Polygon_set_2<ExactKernel>;

/// The ring of `points` (any sequence of ExactPoint) rounded to doubles, reproducibly
/// (acd::internal::RoundToDouble(): CGAL::to_double's result depends on evaluation history).
/// Not always the nearest double: free-space points were seen 1 ulp toward zero from it.
template <typename Points>
acd::Ring2d ToDouble(const Points& points) {
  acd::Ring2d ring;
  ring.reserve(points.size());
  for (const ExactPoint& p : points) {
    ring.push_back(acd::internal::RoundToDouble(p));
  }
  return ring;
}

}  // namespace acdplan::envs::internal
