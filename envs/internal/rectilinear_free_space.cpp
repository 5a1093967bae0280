#include "envs/internal/rectilinear_free_space.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "envs/internal/trace_cells.h"

namespace acdplan::envs::internal {
namespace {

// Calls f(ring) for every ring of every obstacle.
template <typename F>
void ForEachRing(const Workspace2d& workspace, F f) {
  for (const acd::Polygon2d& obstacle : workspace.obstacles) {
    f(obstacle.outer);
    for (const acd::Ring2d& hole : obstacle.holes) f(hole);
  }
}

bool IsRectilinear(const acd::Ring2d& ring) {
  for (size_t i = 0; i < ring.size(); ++i) {
    const acd::Point2d& a = ring[i];
    const acd::Point2d& b = ring[i + 1 == ring.size() ? 0 : i + 1];
    if (a.x() != b.x() && a.y() != b.y()) return false;
  }
  return true;
}

// The bounds' two coordinates along `axis` and every obstacle coordinate strictly between them,
// sorted, without repeats.
std::vector<double> GridLines(const Workspace2d& workspace, int axis) {
  const double low = workspace.bounds.min()[axis], high = workspace.bounds.max()[axis];
  std::vector<double> lines = {low, high};
  ForEachRing(workspace, [&](const acd::Ring2d& ring) {
    for (const acd::Point2d& p : ring) {
      if (p[axis] > low && p[axis] < high) lines.push_back(p[axis]);
    }
  });
  std::sort(lines.begin(), lines.end());
  lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
  return lines;
}

// Index of the grid line at or below `v`, clamped to the grid: every clamped obstacle
// coordinate is a grid line, so the index is exact.
int LineIndex(const std::vector<double>& lines, double v) {
  if (v <= lines.front()) return 0;
  if (v >= lines.back()) return static_cast<int>(lines.size()) - 1;
  return static_cast<int>(std::lower_bound(lines.begin(), lines.end(), v) - lines.begin());
}

double SmallestSpacing(const std::vector<double>& lines) {
  double smallest = std::numeric_limits<double>::infinity();
  for (size_t i = 1; i < lines.size(); ++i) smallest = std::min(smallest, lines[i] - lines[i - 1]);
  return smallest;
}

// Whether moving any grid line by `gap` either way gives a new, distinct double (the chamfer
// points are exact to rounding, as the Boolean construction's rounded points are).
bool GapMovesEveryLine(const std::vector<double>& lines, double gap) {
  const double largest = std::max(std::abs(lines.front()), std::abs(lines.back()));
  const double ulp = std::nextafter(largest, std::numeric_limits<double>::infinity()) - largest;
  return gap >= 4.0 * ulp;
}

}  // namespace

std::optional<std::vector<acd::Polygon2d>> RectilinearFreeSpace(const Workspace2d& workspace,
                                                                double gap) {
  long long vertices = 0;
  bool rectilinear = true;
  ForEachRing(workspace, [&](const acd::Ring2d& ring) {
    rectilinear = rectilinear && IsRectilinear(ring);
    vertices += static_cast<long long>(ring.size());
  });
  if (!rectilinear) return std::nullopt;
  const std::vector<double> xs = GridLines(workspace, 0), ys = GridLines(workspace, 1);
  const int w = static_cast<int>(xs.size()) - 1, h = static_cast<int>(ys.size()) - 1;
  const long long max_cells = std::max(1LL << 22, 64 * vertices);
  if (static_cast<long long>(w) * h > max_cells) return std::nullopt;
  if (!(4.0 * gap < std::min(SmallestSpacing(xs), SmallestSpacing(ys))) ||
      !GapMovesEveryLine(xs, gap) || !GapMovesEveryLine(ys, gap)) {
    return std::nullopt;
  }

  // Winding numbers by rows: a vertical edge adds +1 (going down) or -1 (going up) to every cell
  // east of it in the rows it spans: the obstacles' counter-clockwise outer rings and clockwise
  // holes give each cell the number of obstacles covering it.
  std::vector<int> winding(static_cast<size_t>(w + 1) * h, 0);
  ForEachRing(workspace, [&](const acd::Ring2d& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const acd::Point2d& a = ring[i];
      const acd::Point2d& b = ring[i + 1 == ring.size() ? 0 : i + 1];
      if (a.x() != b.x() || a.x() >= xs.back()) continue;
      const int column = LineIndex(xs, a.x());
      const int row_end = LineIndex(ys, std::max(a.y(), b.y()));
      const int step = b.y() < a.y() ? 1 : -1;
      for (int row = LineIndex(ys, std::min(a.y(), b.y())); row < row_end; ++row) {
        winding[static_cast<size_t>(row) * (w + 1) + column] += step;
      }
    }
  });
  std::vector<std::uint8_t> free(static_cast<size_t>(w) * h);
  for (int row = 0; row < h; ++row) {
    int covering = 0;
    for (int column = 0; column < w; ++column) {
      covering += winding[static_cast<size_t>(row) * (w + 1) + column];
      free[static_cast<size_t>(row) * w + column] = covering == 0 ? 1 : 0;
    }
  }
  return TraceChamfered(w, h, free, xs, ys, gap);
}

}  // namespace acdplan::envs::internal
