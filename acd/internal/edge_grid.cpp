#include "acd/internal/edge_grid.h"

#include <algorithm>
#include <cmath>

namespace acdplan::acd::internal {

EdgeGrid::EdgeGrid(const Polygon2d& polygon) {
  Point2d lower = polygon.outer.front(), upper = polygon.outer.front();
  size_t total = polygon.outer.size();
  for (const Ring2d& hole : polygon.holes) total += hole.size();
  edges_.reserve(total);
  for (int ring = -1; ring < static_cast<int>(polygon.holes.size()); ++ring) {
    const Ring2d& points = ring < 0 ? polygon.outer : polygon.holes[ring];
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      edges_.push_back({ring, i});
      lower = lower.cwiseMin(points[i]);
      upper = upper.cwiseMax(points[i]);
    }
  }
  magnitude_ = std::max(lower.cwiseAbs().maxCoeff(), upper.cwiseAbs().maxCoeff());
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

  // Each edge's bounding box, as the cells' ranges are taken from it in every pass.
  std::vector<Point2d> box_lower, box_upper;
  box_lower.reserve(edges_.size());
  box_upper.reserve(edges_.size());
  for (const Edge& e : edges_) {
    const Ring2d& points = e.ring < 0 ? polygon.outer : polygon.holes[e.ring];
    const Point2d& u = points[e.index];
    const Point2d& w = points[e.index + 1 == static_cast<int>(points.size()) ? 0 : e.index + 1];
    box_lower.push_back(u.cwiseMin(w));
    box_upper.push_back(u.cwiseMax(w));
  }
  const int edge_total = static_cast<int>(edges_.size());
  // Long slanted edges cover many cells with their boxes: coarsen until the lists stay linear.
  std::vector<int> ranges(4 * edges_.size());  // Per edge: first and last column and row.
  for (;; cell *= 2.0) {
    inverse_cell_ = 1.0 / cell;
    columns_ = std::clamp(static_cast<int>(extent.x() * inverse_cell_) + 1, 1, kMaxSide + 1);
    rows_ = std::clamp(static_cast<int>(extent.y() * inverse_cell_) + 1, 1, kMaxSide + 1);
    double covered = 0.0;
    for (int k = 0; k < edge_total; ++k) {
      int* range = &ranges[4 * k];
      range[0] = Column(box_lower[k].x());
      range[1] = Column(box_upper[k].x());
      range[2] = Row(box_lower[k].y());
      range[3] = Row(box_upper[k].y());
      covered += (range[1] - range[0] + 1.0) * (range[3] - range[2] + 1.0);
    }
    if (covered <= 16.0 * edge_count || (columns_ == 1 && rows_ == 1)) break;
  }
  auto for_each_cell = [&](int k, auto f) {
    const int* range = &ranges[4 * k];
    for (int r = range[2]; r <= range[3]; ++r) {
      for (int c = range[0]; c <= range[1]; ++c) f(r * columns_ + c);
    }
  };
  cell_begin_.assign(static_cast<size_t>(columns_) * rows_ + 1, 0);
  for (int k = 0; k < edge_total; ++k) for_each_cell(k, [&](int cell) { ++cell_begin_[cell + 1]; });
  for (size_t i = 1; i < cell_begin_.size(); ++i) cell_begin_[i] += cell_begin_[i - 1];
  cell_edges_.resize(cell_begin_.back());
  std::vector<int> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (int k = 0; k < edge_total; ++k) {
    for_each_cell(k, [&](int cell) { cell_edges_[fill[cell]++] = k; });
  }
  stamp_.assign(edges_.size(), 0);
}

}  // namespace acdplan::acd::internal
