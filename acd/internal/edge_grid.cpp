#include "acd/internal/edge_grid.h"

#include <algorithm>
#include <cmath>

namespace acdplan::acd::internal {

EdgeGrid::EdgeGrid(const Polygon2d& polygon) {
  Point2d lower = polygon.outer.front(), upper = polygon.outer.front();
  for (int ring = -1; ring < static_cast<int>(polygon.holes.size()); ++ring) {
    const Ring2d& points = ring < 0 ? polygon.outer : polygon.holes[ring];
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      edges_.push_back({ring, i});
      lower = lower.cwiseMin(points[i]);
      upper = upper.cwiseMax(points[i]);
    }
  }
  const Point2d extent = upper - lower;
  const double edge_count = static_cast<double>(edges_.size());
  // About one cell per edge, square cells.
  double cell = std::sqrt(std::max(extent.x() * extent.y(), 0.0) / edge_count);
  if (!(cell > 0.0)) cell = std::max(extent.maxCoeff(), 1e-300) / edge_count;
  if (!(cell > 0.0)) cell = 1.0;
  constexpr int kMaxSide = 4096;
  cell = std::max({cell, extent.x() / kMaxSide, extent.y() / kMaxSide});
  x0_ = lower.x();
  y0_ = lower.y();

  auto ring_of = [&](int ring) -> const Ring2d& {
    return ring < 0 ? polygon.outer : polygon.holes[ring];
  };
  auto for_each_cell = [&](const Edge& e, auto f) {
    const Ring2d& points = ring_of(e.ring);
    const Point2d& u = points[e.index];
    const Point2d& w = points[e.index + 1 == static_cast<int>(points.size()) ? 0 : e.index + 1];
    const int c0 = Column(std::min(u.x(), w.x())), c1 = Column(std::max(u.x(), w.x()));
    const int r0 = Row(std::min(u.y(), w.y())), r1 = Row(std::max(u.y(), w.y()));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) f(r * columns_ + c);
    }
  };
  // Long slanted edges cover many cells with their boxes: coarsen until the lists stay linear.
  for (;; cell *= 2.0) {
    inverse_cell_ = 1.0 / cell;
    columns_ = std::clamp(static_cast<int>(extent.x() * inverse_cell_) + 1, 1, kMaxSide + 1);
    rows_ = std::clamp(static_cast<int>(extent.y() * inverse_cell_) + 1, 1, kMaxSide + 1);
    double covered = 0.0;
    for (const Edge& e : edges_) {
      const Ring2d& points = ring_of(e.ring);
      const Point2d& u = points[e.index];
      const Point2d& w = points[e.index + 1 == static_cast<int>(points.size()) ? 0 : e.index + 1];
      covered += (Column(std::max(u.x(), w.x())) - Column(std::min(u.x(), w.x())) + 1.0) *
                 (Row(std::max(u.y(), w.y())) - Row(std::min(u.y(), w.y())) + 1.0);
    }
    if (covered <= 16.0 * edge_count || (columns_ == 1 && rows_ == 1)) break;
  }
  cell_begin_.assign(static_cast<size_t>(columns_) * rows_ + 1, 0);
  for (const Edge& e : edges_) for_each_cell(e, [&](int cell) { ++cell_begin_[cell + 1]; });
  for (size_t i = 1; i < cell_begin_.size(); ++i) cell_begin_[i] += cell_begin_[i - 1];
  cell_edges_.resize(cell_begin_.back());
  std::vector<int> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (int k = 0; k < static_cast<int>(edges_.size()); ++k) {
    for_each_cell(edges_[k], [&](int cell) { cell_edges_[fill[cell]++] = k; });
  }
  stamp_.assign(edges_.size(), 0);
}

}  // namespace acdplan::acd::internal
