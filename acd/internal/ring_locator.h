#pragma once
// Point location in a polygon with holes, used by CheckDecomposition(). Internal.

#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Where a point lies relative to a polygon, with a distance tolerance for the boundary.
enum class PointLocation { kInside, kBoundary, kOutside };

/// Locates points in the region bounded by a set of rings (even-odd rule, so orientation does
/// not matter). Edges are bucketed into horizontal slabs, so a query only visits the edges whose
/// y-range meets the query's: roughly O(1) per query on ordinary shapes instead of O(n).
/// The inside/outside parity uses exact orientation predicates; only the boundary distance is
/// computed in floating point.
class RingLocator {
 public:
  /// Indexes the outer ring and the holes of `polygon` (the locator keeps its own copy).
  explicit RingLocator(const Polygon2d& polygon);

  /// kBoundary if `p` is within `tolerance` of an edge, else kInside or kOutside.
  PointLocation Locate(const Point2d& p, double tolerance) const;

  /// True if `p` is within `tolerance` of an edge.
  bool NearBoundary(const Point2d& p, double tolerance) const;

  /// Exact even-odd parity of `p` (points exactly on an edge may go either way).
  bool InsideParity(const Point2d& p) const;

  /// Distance from `p` to the nearest edge (visits every edge: O(n)).
  double BoundaryDistance(const Point2d& p) const;

 private:
  struct Edge {
    Point2d a, b;
  };
  int Slab(double y) const;

  std::vector<Edge> edges_;
  double y_min_ = 0.0, y_max_ = -1.0, x_min_ = 0.0, x_max_ = -1.0;
  double inverse_height_ = 0.0;  // Slabs per unit of y.
  int slab_count_ = 1;
  std::vector<int> slab_begin_;  // CSR offsets into slab_edges_, slab_count_ + 1 entries.
  std::vector<int> slab_edges_;
};

/// Distance from `p` to the segment [a, b].
double SegmentDistance(const Point2d& p, const Point2d& a, const Point2d& b);

}  // namespace acdplan::acd::internal
