#include "acd/internal/triangulate_ring.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "acd/internal/exact_predicates.h"

namespace acdplan::acd::internal {
namespace {

// Ear clipping on a doubly linked list of the ring's vertices (Meisters' two-ears theorem;
// O'Rourke, "Computational Geometry in C", Ch. 1). A strictly convex vertex b with neighbours
// a, c is an ear when no reflex vertex lies in the closed triangle (a, b, c): if any vertex lay
// inside, the one farthest from the line ac would have the triangle's side of its supporting
// line locally inside the polygon, so it (or an end of its collinear run) would be reflex.
// Clipping an ear only shrinks its neighbours' interior angles, so a vertex never turns from
// convex to reflex and the reflex vertices can be indexed once, in a uniform grid, and removed
// lazily. Worst case O(n^2); about O(n) ear tests of O(1) grid cells each on typical input.
class EarClipper {
 public:
  explicit EarClipper(const Ring2d& ring)
      : p_(ring),
        n_(static_cast<int>(ring.size())),
        prev_(n_),
        next_(n_),
        turn_(n_),
        reflex_(n_, 0),
        alive_(n_, 1) {
    for (int i = 0; i < n_; ++i) {
      prev_[i] = i == 0 ? n_ - 1 : i - 1;
      next_[i] = i == n_ - 1 ? 0 : i + 1;
    }
    std::vector<int> reflex_vertices;
    for (int i = 0; i < n_; ++i) {
      turn_[i] = static_cast<int8_t>(Orientation(p_[prev_[i]], p_[i], p_[next_[i]]));
      if (turn_[i] < 0) {
        reflex_[i] = 1;
        reflex_vertices.push_back(i);
      }
    }
    BuildGrid(reflex_vertices);
  }

  std::vector<std::array<int, 3>> Run() {
    std::vector<std::array<int, 3>> triangles;
    triangles.reserve(n_ - 2);
    remaining_ = n_;
    int last = 0;  // A vertex still in the ring.
    for (int v = 0; v < n_; ++v) {
      if (remaining_ > 3 && alive_[v] && IsSpike(v)) last = ClipAndSweepSpikes(v, &triangles);
    }
    // Candidate ears, most recent on top. Clipping b only changes the angles at its neighbours,
    // so they are re-tested at once: on band-like pockets (spirals) the ears live only at the
    // band's ends and this walks them as a zipper, where lap-based ear search is O(n^2). Clipping
    // can also turn a reflex vertex convex and so unblock an ear elsewhere: that ear is found by
    // a full lap once the candidates run out.
    std::vector<int> candidates;
    while (remaining_ > 3) {
      if (candidates.empty()) {
        int v = last;
        do {
          if (IsEar(v)) candidates.push_back(v);
          v = prev_[v];  // Pushed backwards, so popped in ring order.
        } while (v != last);
        if (candidates.empty()) {  // No ear at all (degenerate input): force a clip.
          last = ClipAndSweepSpikes(PickFallback(last), &triangles);
          candidates.push_back(next_[last]);
          candidates.push_back(last);
          continue;
        }
      }
      const int b = candidates.back();
      candidates.pop_back();
      if (!alive_[b] || !IsEar(b)) continue;
      last = ClipAndSweepSpikes(b, &triangles);
      candidates.push_back(next_[last]);
      candidates.push_back(last);
    }
    triangles.push_back({prev_[last], last, next_[last]});
    return triangles;
  }

 private:
  void BuildGrid(const std::vector<int>& reflex_vertices) {
    const int r = static_cast<int>(reflex_vertices.size());
    if (r == 0) return;
    min_x_ = max_x_ = p_[reflex_vertices[0]].x();
    min_y_ = max_y_ = p_[reflex_vertices[0]].y();
    for (int v : reflex_vertices) {
      min_x_ = std::min(min_x_, p_[v].x());
      max_x_ = std::max(max_x_, p_[v].x());
      min_y_ = std::min(min_y_, p_[v].y());
      max_y_ = std::max(max_y_, p_[v].y());
    }
    // About two reflex vertices per cell; a single cell (a plain list) for small rings.
    const double w = max_x_ - min_x_;
    const double h = max_y_ - min_y_;
    if (r >= 16 && w > 0.0 && h > 0.0) {
      const double cells = 0.5 * r;
      // Clamped before the conversion: w / h can exceed any int (a ring 1e30 wide, 1 high).
      nx_ = static_cast<int>(std::clamp(std::sqrt(cells * w / h), 1.0, static_cast<double>(r)));
      ny_ = std::clamp(static_cast<int>(cells / nx_), 1, r);
    } else if (r >= 16) {
      (w > 0.0 ? nx_ : ny_) = std::max(1, r / 2);
    }
    inv_cell_x_ = w > 0.0 ? nx_ / w : 0.0;
    inv_cell_y_ = h > 0.0 ? ny_ / h : 0.0;
    cell_start_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
    for (int v : reflex_vertices) ++cell_start_[CellOf(v) + 1];
    for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    cell_items_.resize(r);
    std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (int v : reflex_vertices) cell_items_[fill[CellOf(v)]++] = v;
    cell_end_ = fill;
  }

  // Cells cover the reflex vertices' box; a point outside it (at any distance: its offset in
  // cells may exceed int's range, where converting it would be undefined) is clamped in double
  // first, into a border cell. NaN (an infinite offset times a zero scale) goes to cell 0.
  static int ClampedCell(double t, int count) {
    if (!(t > 0.0)) return 0;
    if (t >= count - 1) return count - 1;
    return static_cast<int>(t);
  }
  int CellX(double x) const { return ClampedCell((x - min_x_) * inv_cell_x_, nx_); }
  int CellY(double y) const { return ClampedCell((y - min_y_) * inv_cell_y_, ny_); }
  int CellOf(int v) const { return CellY(p_[v].y()) * nx_ + CellX(p_[v].x()); }

  // Whether reflex vertex q prevents clipping the ear (a, b, c) (counter-clockwise).
  bool Blocks(int q, int a, int b, int c) const {
    const Point2d& x = p_[q];
    // Weakly simple rings repeat a position: a copy of a triangle corner blocks only when one of
    // its edges enters the triangle, i.e. leaves the corner strictly inside the corner's cone.
    if (x == p_[a]) return EdgeEntersCorner(q, a, b, c);
    if (x == p_[b]) return EdgeEntersCorner(q, b, c, a);
    if (x == p_[c]) return EdgeEntersCorner(q, c, a, b);
    return Orientation(p_[a], p_[b], x) >= 0 && Orientation(p_[b], p_[c], x) >= 0 &&
           Orientation(p_[c], p_[a], x) >= 0;
  }

  // Corner `corner` of a counter-clockwise triangle, followed by `after` and preceded by
  // `before`: does an edge of q (at the corner's position) point strictly into the corner?
  bool EdgeEntersCorner(int q, int corner, int after, int before) const {
    for (int end : {prev_[q], next_[q]}) {
      if (Orientation(p_[corner], p_[after], p_[end]) > 0 &&
          Orientation(p_[corner], p_[before], p_[end]) < 0) {
        return true;
      }
    }
    return false;
  }

  // Widens [*x_min, *x_max] by the x-extent of the part of segment pq with y in [lo, hi].
  static void SliceEdge(const Point2d& p, const Point2d& q, double lo, double hi, double* x_min,
                        double* x_max) {
    const double y_from = std::max(lo, std::min(p.y(), q.y()));
    const double y_to = std::min(hi, std::max(p.y(), q.y()));
    if (y_from > y_to) return;
    double xa = p.x(), xb = q.x();
    if (p.y() != q.y()) {
      const double slope = (q.x() - p.x()) / (q.y() - p.y());
      xa = p.x() + slope * (y_from - p.y());
      xb = p.x() + slope * (y_to - p.y());
    }
    *x_min = std::min({*x_min, xa, xb});
    *x_max = std::max({*x_max, xa, xb});
  }

  bool IsEar(int b) {
    if (turn_[b] <= 0) return false;
    const int a = prev_[b];
    const int c = next_[b];
    for (int q : late_reflex_) {
      if (reflex_[q] && q != a && q != c && Blocks(q, a, b, c)) return false;
    }
    if (cell_items_.empty()) return true;
    const double x0 = std::min({p_[a].x(), p_[b].x(), p_[c].x()});
    const double x1 = std::max({p_[a].x(), p_[b].x(), p_[c].x()});
    const double y0 = std::min({p_[a].y(), p_[b].y(), p_[c].y()});
    const double y1 = std::max({p_[a].y(), p_[b].y(), p_[c].y()});
    if (x1 < min_x_ || x0 > max_x_ || y1 < min_y_ || y0 > max_y_) return true;
    // Visit, row by row, only the cells the triangle's slice of that row overlaps (long thin
    // ears would otherwise scan their whole bounding box). The slack only widens the search;
    // the decision per vertex is exact.
    const double slack = 1e-9 * ((x1 - x0) + (y1 - y0) + std::abs(x0) + std::abs(y0));
    const double cell_h = inv_cell_y_ > 0.0 ? 1.0 / inv_cell_y_ : 0.0;
    const int cy0 = CellY(y0), cy1 = CellY(y1);
    for (int cy = cy0; cy <= cy1; ++cy) {
      // The row's y-band, cut to the triangle and to the reflex vertices' extent.
      const double lo = std::max(cy == cy0 ? y0 : min_y_ + cy * cell_h - slack, min_y_ - slack);
      const double hi =
          std::min(cy == cy1 ? y1 : min_y_ + (cy + 1) * cell_h + slack, max_y_ + slack);
      double xa = x1, xb = x0;
      SliceEdge(p_[a], p_[b], lo, hi, &xa, &xb);
      SliceEdge(p_[b], p_[c], lo, hi, &xa, &xb);
      SliceEdge(p_[c], p_[a], lo, hi, &xa, &xb);
      if (xa > xb) continue;
      const int cx0 = CellX(xa - slack), cx1 = CellX(xb + slack);
      for (int cx = cx0; cx <= cx1; ++cx) {
        const int cell = cy * nx_ + cx;
        for (int k = cell_start_[cell]; k < cell_end_[cell]; ++k) {
          const int q = cell_items_[k];
          if (!reflex_[q]) {  // No longer reflex (for good): drop it from the cell.
            cell_items_[k--] = cell_items_[--cell_end_[cell]];
            continue;
          }
          if (q == a || q == c) continue;
          const Point2d& x = p_[q];
          if (x.x() < x0 || x.x() > x1 || x.y() < y0 || x.y() > y1) continue;
          if (Blocks(q, a, b, c)) return false;
        }
      }
    }
    return true;
  }

  // A vertex whose two edges leave in the same direction (an antenna tip, or a zero-length
  // edge): clipping it adds a zero-area triangle and leaves the region unchanged. Clipping them
  // at once keeps degenerate (weakly simple) remainders from posing as ears.
  bool IsSpike(int v) const {
    return turn_[v] == 0 && (p_[prev_[v]] - p_[v]).dot(p_[next_[v]] - p_[v]) >= 0.0;
  }

  // Clips b, then every neighbour that became a spike; returns a surviving vertex next to the
  // last clip.
  int ClipAndSweepSpikes(int b, std::vector<std::array<int, 3>>* triangles) {
    int survivor = Clip(b, triangles);
    for (bool swept = true; swept && remaining_ > 3;) {
      swept = false;
      for (int v : {prev_[survivor], survivor, next_[survivor]}) {
        if (remaining_ > 3 && IsSpike(v)) {
          survivor = Clip(v, triangles);
          swept = true;
          break;
        }
      }
    }
    return survivor;
  }

  // Returns the vertex before b.
  int Clip(int b, std::vector<std::array<int, 3>>* triangles) {
    const int a = prev_[b];
    const int c = next_[b];
    triangles->push_back({a, b, c});
    next_[a] = c;
    prev_[c] = a;
    reflex_[b] = 0;
    alive_[b] = 0;
    --remaining_;
    UpdateTurn(a);
    UpdateTurn(c);
    return a;
  }

  void UpdateTurn(int v) {
    turn_[v] = static_cast<int8_t>(Orientation(p_[prev_[v]], p_[v], p_[next_[v]]));
    if (turn_[v] >= 0) {
      reflex_[v] = 0;
    } else if (!reflex_[v]) {
      // Only after a forced (fallback) clip: keep it testable outside the grid.
      reflex_[v] = 1;
      late_reflex_.push_back(v);
    }
  }

  // No ear in a full lap (degenerate input): clip the least harmful vertex so the loop always
  // terminates with n - 2 triangles. Preference: a collinear vertex (zero-area triangle that
  // leaves the region unchanged), then a convex vertex whose triangle has no reflex vertex in
  // its open interior (only boundary contacts), then any convex vertex, then `start`.
  int PickFallback(int start) const {
    int v = start;
    do {
      if (turn_[v] == 0) return v;
      v = next_[v];
    } while (v != start);
    int any_convex = -1;
    v = start;
    do {
      if (turn_[v] > 0) {
        if (any_convex < 0) any_convex = v;
        if (!HasReflexStrictlyInside(v)) return v;
      }
      v = next_[v];
    } while (v != start);
    return any_convex >= 0 ? any_convex : start;
  }

  bool HasReflexStrictlyInside(int b) const {
    const int a = prev_[b];
    const int c = next_[b];
    for (int q = next_[c]; q != a; q = next_[q]) {
      if (reflex_[q] && Orientation(p_[a], p_[b], p_[q]) > 0 &&
          Orientation(p_[b], p_[c], p_[q]) > 0 && Orientation(p_[c], p_[a], p_[q]) > 0) {
        return true;
      }
    }
    return false;
  }

  const Ring2d& p_;
  int n_;
  std::vector<int> prev_, next_;
  std::vector<int8_t> turn_;     // Orientation(prev, v, next) in the current (clipped) ring.
  std::vector<uint8_t> reflex_;  // Alive and reflex: the only vertices that block an ear.
  std::vector<uint8_t> alive_;
  std::vector<int> late_reflex_;
  int remaining_ = 0;
  // Uniform grid over the initially reflex vertices (counting-sorted into cells).
  double min_x_ = 0, max_x_ = 0, min_y_ = 0, max_y_ = 0, inv_cell_x_ = 0, inv_cell_y_ = 0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> cell_start_, cell_end_, cell_items_;
};

}  // namespace

std::vector<std::array<int, 3>> TriangulateRing(const Ring2d& ring) {
  if (ring.size() < 3) {
    throw std::invalid_argument("TriangulateRing(): the ring needs at least 3 vertices, got " +
                                std::to_string(ring.size()));
  }
  if (ring.size() == 3) return {{0, 1, 2}};
  return EarClipper(ring).Run();
}

}  // namespace acdplan::acd::internal
