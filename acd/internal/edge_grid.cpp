#include "acd/internal/edge_grid.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace acdplan::acd::internal {

void EdgeGrid::Build(const Polygon2d& polygon) {
  size_t total = polygon.outer.size();
  for (const Ring2d& hole : polygon.holes) total += hole.size();
  // Stores through a local pointer and bounds in scalars: with push_back() the compiler reloaded
  // the ring's size and the vector's end after every store (they might alias), which took a
  // third of the build on neuron.poly.
  edges_.resize(total);
  double x_lo = polygon.outer.front().x(), x_hi = x_lo;
  double y_lo = polygon.outer.front().y(), y_hi = y_lo;
  Edge* edge = edges_.data();
  for (int ring = -1; ring < static_cast<int>(polygon.holes.size()); ++ring) {
    const Ring2d& points = ring < 0 ? polygon.outer : polygon.holes[ring];
    const int n = static_cast<int>(points.size());
    for (int i = 0; i < n; ++i) {
      *edge++ = {ring, i};
      const double x = points[i].x(), y = points[i].y();
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, y);
    }
  }
  const Point2d lower(x_lo, y_lo), upper(x_hi, y_hi);
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

  // The cells of each edge's bounding box span the cells of its two ends: Column() and Row()
  // are monotone, so the cell of a box corner is the least or greatest of the ends' cells. So
  // each pass rounds every vertex once rather than every box corner.
  const int edge_total = static_cast<int>(edges_.size());
  // Per vertex, in edge order: column, row; per edge: first and last column and row.
  scratch_.resize(6 * edges_.size());
  int* const vertex_cells = scratch_.data();
  int* const ranges = vertex_cells + 2 * edges_.size();
  // Long slanted edges cover many cells with their boxes: coarsen until the lists stay linear.
  for (;; cell *= 2.0) {
    inverse_cell_ = 1.0 / cell;
    columns_ = std::clamp(static_cast<int>(extent.x() * inverse_cell_) + 1, 1, kMaxSide + 1);
    rows_ = std::clamp(static_cast<int>(extent.y() * inverse_cell_) + 1, 1, kMaxSide + 1);
    int k = 0;
    for (int ring = -1; ring < static_cast<int>(polygon.holes.size()); ++ring) {
      for (const Point2d& p : ring < 0 ? polygon.outer : polygon.holes[ring]) {
        vertex_cells[2 * k] = Column(p.x());
        vertex_cells[2 * k + 1] = Row(p.y());
        ++k;
      }
    }
    double covered = 0.0;
    for (int first = 0; first < edge_total;) {  // Ring by ring: its edges are edges_[first, last).
      const int ring = edges_[first].ring;
      const int last =
          first + static_cast<int>(ring < 0 ? polygon.outer.size() : polygon.holes[ring].size());
      for (int e = first; e < last; ++e) {
        const int* u = &vertex_cells[2 * e];
        const int* w = &vertex_cells[2 * (e + 1 == last ? first : e + 1)];
        int* range = &ranges[4 * e];
        std::tie(range[0], range[1]) = std::minmax(u[0], w[0]);
        std::tie(range[2], range[3]) = std::minmax(u[1], w[1]);
        covered += (range[1] - range[0] + 1.0) * (range[3] - range[2] + 1.0);
      }
      first = last;
    }
    if (covered <= 16.0 * edge_count || (columns_ == 1 && rows_ == 1)) break;
  }
  // Local copies: the compiler cannot keep members in registers across stores through int
  // pointers (they may alias columns_).
  const int columns = columns_;
  auto for_each_cell = [ranges, columns](int k, auto f) {
    const int* range = &ranges[4 * k];
    for (int r = range[2]; r <= range[3]; ++r) {
      for (int c = range[0]; c <= range[1]; ++c) f(r * columns + c);
    }
  };
  cell_begin_.assign(static_cast<size_t>(columns_) * rows_ + 1, 0);
  int* const count = cell_begin_.data() + 1;
  for (int k = 0; k < edge_total; ++k) for_each_cell(k, [count](int cell) { ++count[cell]; });
  for (size_t i = 1; i < cell_begin_.size(); ++i) cell_begin_[i] += cell_begin_[i - 1];
  cell_edges_.resize(cell_begin_.back());
  next_slot_.assign(cell_begin_.begin(), cell_begin_.end() - 1);
  int* const next = next_slot_.data();
  int* const listed = cell_edges_.data();
  for (int k = 0; k < edge_total; ++k) {
    for_each_cell(k, [next, listed, k](int cell) { listed[next[cell]++] = k; });
  }
  stamp_.assign(edges_.size(), 0);
}

std::size_t EdgeGrid::HeldBytes() const {
  return edges_.capacity() * sizeof(Edge) +
         (cell_begin_.capacity() + cell_edges_.capacity() + scratch_.capacity() +
          next_slot_.capacity()) *
             sizeof(int) +
         stamp_.capacity() * sizeof(std::uint32_t);
}

}  // namespace acdplan::acd::internal
