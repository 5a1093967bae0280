#pragma once
// A uniform grid over the edges of a polygon with holes, for segment and nearest-point queries
// during Resolve. Internal.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// The edges of all rings of a polygon bucketed in a uniform grid of about one cell per edge.
/// An edge is listed in every cell its bounding box meets. A query reports each edge whose box
/// may meet a segment's padded corridor at most once; it is conservative (cells are selected
/// with one cell of slack against rounding), never exact: callers decide with exact predicates.
/// Building is O(n + total cells covered); a query costs the cells the corridor crosses plus
/// the edges listed there, instead of O(n) for a scan of all edges. VisitRing() serves searches
/// for the edges nearest to a point (NearestAccepted(), acd/internal/nearest_boundary.h).
class EdgeGrid {
 public:
  /// An edge: `index` -> `index` + 1 of ring `ring` (-1: the outer ring; k >= 0: hole k).
  struct Edge {
    int ring;
    int index;
  };

  EdgeGrid() = default;
  explicit EdgeGrid(const Polygon2d& polygon) { Build(polygon); }

  /// Builds the grid over `polygon` anew, in the storage already held (Resolve keeps one grid
  /// per thread: a fresh one's storage came from memory not touched lately, at a cache miss
  /// per line).
  void Build(const Polygon2d& polygon);

  /// Calls `visit(edge)` for every edge that may come within `pad` of the segment a-b, cells
  /// from a toward b, until `visit` returns true (then returns true). Not thread-safe (a scratch
  /// stamp per edge).
  template <typename Visit>
  bool AnyNear(const Point2d& a, const Point2d& b, double pad, Visit visit) const;

  /// For searches that grow outward from `p` one ring of cells at a time: calls `visit(edge)`
  /// for every edge listed in a cell at Chebyshev distance `ring` from the cell of p (ring 0:
  /// that cell alone), once per such cell. Returns a lower bound on the distance from p to the
  /// bounding box of every edge listed in no cell of rings 0..`ring` (the bound allows for the
  /// rounding in assigning cells), or +infinity once those rings cover the grid. Thread-safe.
  template <typename Visit>
  double VisitRing(const Point2d& p, int ring, Visit visit) const;

  /// The storage held, and its release (acd/internal/thread_scratch.h).
  std::size_t HeldBytes() const;
  void Release() { *this = EdgeGrid(); }

  /// The largest magnitude of a vertex coordinate: the scale of rounding noise.
  double Magnitude() const { return magnitude_; }

 private:
  int Column(double x) const;
  int Row(double y) const;

  std::vector<Edge> edges_;
  double x0_ = 0.0, y0_ = 0.0, inverse_cell_ = 1.0;
  double magnitude_ = 0.0;
  int columns_ = 1, rows_ = 1;
  std::vector<int> cell_begin_;  // CSR offsets into cell_edges_, columns_ * rows_ + 1 entries.
  std::vector<int> cell_edges_;
  // Build()'s: per vertex its cell, per edge its cell range; per cell its next free slot.
  std::vector<int> scratch_, next_slot_;
  mutable std::vector<std::uint32_t> stamp_;  // Per edge: the query that last reported it.
  mutable std::uint32_t query_ = 0;
};

// floor((x - x0) / cell) clamped to the grid: clamped first, the value is >= 0, where the
// conversion's truncation is the floor (and far cheaper than std::floor without SSE4.1).
inline int EdgeGrid::Column(double x) const {
  return static_cast<int>(
      std::clamp((x - x0_) * inverse_cell_, 0.0, static_cast<double>(columns_ - 1)));
}

inline int EdgeGrid::Row(double y) const {
  return static_cast<int>(
      std::clamp((y - y0_) * inverse_cell_, 0.0, static_cast<double>(rows_ - 1)));
}

template <typename Visit>
bool EdgeGrid::AnyNear(const Point2d& a, const Point2d& b, double pad, Visit visit) const {
  if (++query_ == 0) {  // Wrapped around: forget old stamps.
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
  const double xlo = std::min(a.x(), b.x()) - pad, xhi = std::max(a.x(), b.x()) + pad;
  const int c0 = Column(xlo), c1 = Column(xhi);
  const double dx = b.x() - a.x();
  // Cells from a's end toward b's, so that a blocker near a (the usual case: a cut from a hole
  // vertex past its neighbours) ends the walk early.
  const int column_step = a.x() <= b.x() ? 1 : -1;
  const bool rows_up = a.y() <= b.y();
  for (int c = column_step > 0 ? c0 : c1; c0 <= c && c <= c1; c += column_step) {
    // The segment's y-range over this column's x-range (plus the pad), or its whole y-range
    // when it is (nearly) vertical; one row of slack each way absorbs rounding.
    double ylo = std::min(a.y(), b.y()), yhi = std::max(a.y(), b.y());
    if (dx != 0.0 && c0 != c1) {
      const double cx0 = std::max(xlo, x0_ + c / inverse_cell_ - pad);
      const double cx1 = std::min(xhi, x0_ + (c + 1) / inverse_cell_ + pad);
      const double t0 = std::clamp((cx0 - a.x()) / dx, 0.0, 1.0);
      const double t1 = std::clamp((cx1 - a.x()) / dx, 0.0, 1.0);
      const double y_at0 = a.y() + t0 * (b.y() - a.y()), y_at1 = a.y() + t1 * (b.y() - a.y());
      ylo = std::max(ylo, std::min(y_at0, y_at1));
      yhi = std::min(yhi, std::max(y_at0, y_at1));
    }
    const int r0 = std::max(0, Row(ylo - pad) - 1), r1 = std::min(rows_ - 1, Row(yhi + pad) + 1);
    for (int k = 0; k <= r1 - r0; ++k) {
      const int cell = (rows_up ? r0 + k : r1 - k) * columns_ + c;
      for (int k = cell_begin_[cell]; k < cell_begin_[cell + 1]; ++k) {
        const int e = cell_edges_[k];
        if (stamp_[e] == query_) continue;
        stamp_[e] = query_;
        if (visit(edges_[e])) return true;
      }
    }
  }
  return false;
}

template <typename Visit>
double EdgeGrid::VisitRing(const Point2d& p, int ring, Visit visit) const {
  const int c = Column(p.x()), r = Row(p.y());
  const int c0 = c - ring, c1 = c + ring, r0 = r - ring, r1 = r + ring;
  auto visit_cell = [&](int column, int row) {
    if (column < 0 || column >= columns_ || row < 0 || row >= rows_) return;
    const int cell = row * columns_ + column;
    for (int k = cell_begin_[cell]; k < cell_begin_[cell + 1]; ++k) visit(edges_[cell_edges_[k]]);
  };
  for (int column = std::max(c0, 0); column <= std::min(c1, columns_ - 1); ++column) {
    visit_cell(column, r0);
    if (r1 != r0) visit_cell(column, r1);
  }
  for (int row = std::max(r0 + 1, 0); row <= std::min(r1 - 1, rows_ - 1); ++row) {
    visit_cell(c0, row);
    visit_cell(c1, row);
  }
  // An edge listed in no visited cell has its box in columns left of c0 (so t(x) < c0 for all
  // its points, t(x) = (x - x0) / cell as Column() rounds it: monotone in x), right of c1, below
  // r0 or above r1. The gap to p in cells, on each side the grid extends past the visited ones.
  const double tx = (p.x() - x0_) * inverse_cell_, ty = (p.y() - y0_) * inverse_cell_;
  double gap = std::numeric_limits<double>::infinity();
  if (c0 > 0) gap = std::min(gap, tx - c0);
  if (c1 < columns_ - 1) gap = std::min(gap, c1 + 1 - tx);
  if (r0 > 0) gap = std::min(gap, ty - r0);
  if (r1 < rows_ - 1) gap = std::min(gap, r1 + 1 - ty);
  if (gap == std::numeric_limits<double>::infinity()) return gap;
  // t is off by a few ulps of x - x0: allow a thousand times that.
  const double slack = 1e-12 * (magnitude_ + p.cwiseAbs().maxCoeff());
  return std::max(0.0, gap / inverse_cell_ * (1.0 - 1e-12) - slack);
}

}  // namespace acdplan::acd::internal
