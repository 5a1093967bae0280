#pragma once
// The free space of a 2D workspace: bounds minus the union of the obstacles.

#include <vector>

#include "acd/polygon2d.h"
#include "envs/workspace2d.h"

namespace acdplan::envs {

/// Options for FreeSpace2d(); `{}` is valid.
struct FreeSpace2dOptions {
  /// Half-diagonal of the small square (a diamond, |dx| + |dy| <= gap) added to the obstacles
  /// at each pinch where a hole would touch another ring, relative to the bounds' diagonal;
  /// > 0. Each such pinch removes at most 2 gap^2 of free area.
  double pinch_gap = 1e-7;
};

/// The free space `workspace.bounds` minus the union of `workspace.obstacles`: a list of valid,
/// clean polygons with holes (as acd::PreparePolygon() leaves them), one per connected region,
/// ready for acd::Decompose2d(). Sorted by their lowest-leftmost vertex (then by their rings).
///
/// Obstacles may overlap, touch each other, touch or cross the bounds, or split the free space
/// into several regions. A region is a connected open set (one face of the arrangement, one
/// 4-connected set of grid cells); where the free space's boundary passes twice through a point:
///  - two regions meeting there (lobes, or regions round an obstacle between them) are two
///    polygons, exactly (a zero-width passage is no passage; the split is where the topology
///    already is);
///  - one region touching itself there (a hole touching its outer ring or another of its holes,
///    which no set of simple, disjoint rings describes) is closed by adding a diamond of
///    half-diagonal `pinch_gap` * diagonal to the obstacles there; the free space only shrinks
///    (collision stays conservative) and the pinch point was not traversable anyway.
/// The result may be empty (obstacles cover the bounds).
///
/// Construction: when every obstacle edge is axis-parallel (grid maps, box worlds), the free
/// cells of the grid of the obstacles' coordinates are traced (envs/internal/
/// rectilinear_free_space.h; linear in the cells; valid by construction); otherwise exact
/// Boolean operations (CGAL Boolean_set_operations_2, exact constructions) build it, one
/// polygon per face of their arrangement, rounded to doubles and checked by
/// acd::PreparePolygon(). Both give the same polygons (a diamond's points may differ in the last
/// bit: the trace adds in doubles, the Booleans round exact values).
/// @throws InputError if the bounds are empty or an obstacle is invalid, or
///         `options.pinch_gap` <= 0.
std::vector<acd::Polygon2d> FreeSpace2d(const Workspace2d& workspace,
                                        const FreeSpace2dOptions& options = {});

}  // namespace acdplan::envs
