#include "envs/internal/trace_cells.h"

#include <array>
#include <stdexcept>
#include <utility>

namespace acdplan::envs::internal {
namespace {

// Labels the 4-connected components of the cells set in a mask (blocked cells, or free ones) and
// traces their boundaries. Grid corners are (X, Y) with X in [0, w], Y in [0, h]; the corner
// (X, Y) has the cells NE = (X, Y), NW = (X - 1, Y), SW = (X - 1, Y - 1), SE = (X, Y - 1) around
// it.
class Tracer {
 public:
  Tracer(int w, int h, const std::vector<std::uint8_t>& mask)
      : mask_(mask), w_(w), h_(h), label_(static_cast<size_t>(w) * h, -1), cut_(label_.size(), 0) {
    for (int i = 0; i < w * h; ++i) {
      if (mask[i] && label_[i] < 0) {
        cells_.emplace_back();
        Flood(i, -1, static_cast<int>(cells_.size()) - 1);
      }
    }
  }

  int Label(int x, int y) const {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return -1;
    return label_[Index(x, y)];
  }

  // The label whose two diagonal cells meet at corner (X, Y) while the other two cells are
  // not in it (its boundary would pass twice through the corner), or -1.
  int PinchLabel(int x, int y) const {
    const int sw = Label(x - 1, y - 1), se = Label(x, y - 1);
    const int nw = Label(x - 1, y), ne = Label(x, y);
    if (sw >= 0 && sw == ne && se != sw && nw != sw) return sw;
    if (nw >= 0 && nw == se && ne != nw && sw != nw) return nw;
    return -1;
  }

  // Removes every pinch: a pinched label is cut along the horizontal grid line through the
  // pinch (all vertical adjacencies of its cells across that line), then re-labelled. Cutting
  // only splits labels, so it never creates a pinch; one scan with a re-check suffices.
  void CutPinches() {
    std::vector<std::pair<int, int>> candidates;
    for (int y = 1; y < h_; ++y) {
      for (int x = 1; x < w_; ++x) {
        if (PinchLabel(x, y) >= 0) candidates.emplace_back(x, y);
      }
    }
    for (const auto& [x, y] : candidates) {
      const int label = PinchLabel(x, y);
      if (label < 0) continue;
      for (int i : cells_[label]) {
        const int cx = i % w_, cy = i / w_;
        if (cy == y && Label(cx, y - 1) == label) cut_[i] = 1;
      }
      Relabel(label);
      if (PinchLabel(x, y) >= 0) throw std::logic_error("TraceCells: pinch cut failed");
    }
  }

  // The boundary rings of every label, keeping the label on the left. A corner where the
  // label pinches (both passes of its boundary; none is left after CutPinches()) is cut off by
  // `chamfer`: the ring passes through the points `chamfer` before and after it on its edges.
  std::vector<acd::Polygon2d> Trace(const std::vector<double>& xs, const std::vector<double>& ys,
                                    double chamfer) const {
    std::vector<acd::Polygon2d> polygons(cells_.size());
    std::vector<char> has_outer(cells_.size(), 0);
    std::vector<std::uint8_t> visited(label_.size(), 0);  // Bottom edge of a cell walked.
    static constexpr std::array<int, 4> kDx = {1, 0, -1, 0}, kDy = {0, 1, 0, -1};
    for (int cy = 0; cy < h_; ++cy) {
      for (int cx = 0; cx < w_; ++cx) {
        const int label = Label(cx, cy);
        if (label < 0 || Label(cx, cy - 1) == label || visited[Index(cx, cy)]) continue;
        // Walk with the label on the left, starting east along the cell's bottom edge.
        struct Corner {
          int x, y, in, out;  // Grid corner; directions of the edges into and out of it.
        };
        std::vector<Corner> corners;
        int x = cx, y = cy, d = 0;
        do {
          if (d == 0) visited[Index(x, y)] = 1;
          x += kDx[d];
          y += kDy[d];
          int ahead_left, ahead_right;
          switch (d) {
            case 0:
              ahead_left = Label(x, y);
              ahead_right = Label(x, y - 1);
              break;
            case 1:
              ahead_left = Label(x - 1, y);
              ahead_right = Label(x, y);
              break;
            case 2:
              ahead_left = Label(x - 1, y - 1);
              ahead_right = Label(x - 1, y);
              break;
            default:
              ahead_left = Label(x, y - 1);
              ahead_right = Label(x - 1, y - 1);
              break;
          }
          const int next = ahead_left != label    ? (d + 1) % 4
                           : ahead_right == label ? (d + 3) % 4
                                                  : d;
          if (next != d) corners.push_back({x, y, d, next});
          d = next;
        } while (!(x == cx && y == cy && d == 0));
        long long twice_area = 0;
        for (size_t i = 0; i < corners.size(); ++i) {
          const Corner& a = corners[i];
          const Corner& b = corners[(i + 1) % corners.size()];
          twice_area += static_cast<long long>(a.x) * b.y - static_cast<long long>(b.x) * a.y;
        }
        acd::Ring2d ring;
        ring.reserve(corners.size());
        for (const Corner& c : corners) {
          const acd::Point2d p(xs[c.x], ys[c.y]);
          if (PinchLabel(c.x, c.y) != label) {
            ring.push_back(p);
            continue;
          }
          ring.push_back(p - chamfer * acd::Point2d(kDx[c.in], kDy[c.in]));
          ring.push_back(p + chamfer * acd::Point2d(kDx[c.out], kDy[c.out]));
        }
        if (twice_area > 0) {
          if (has_outer[label]) throw std::logic_error("TraceCells: two outer rings");
          has_outer[label] = 1;
          polygons[label].outer = std::move(ring);
        } else {
          polygons[label].holes.push_back(std::move(ring));
        }
      }
    }
    return polygons;
  }

 private:
  int Index(int x, int y) const { return y * w_ + x; }

  // Labels the 4-connected (through uncut adjacencies) cells of label `from` (-1: unlabelled
  // cells of the mask) reachable from cell `start` with `to`.
  void Flood(int start, int from, int to) {
    std::vector<int> stack = {start};
    label_[start] = to;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      cells_[to].push_back(i);
      const int x = i % w_, y = i / w_;
      auto visit = [&](int nx, int ny, bool open) {
        if (!open || nx < 0 || ny < 0 || nx >= w_ || ny >= h_) return;
        const int j = Index(nx, ny);
        if (label_[j] != from || (from == -1 && !mask_[j])) return;
        label_[j] = to;
        stack.push_back(j);
      };
      visit(x + 1, y, true);
      visit(x - 1, y, true);
      visit(x, y + 1, y + 1 < h_ && !cut_[Index(x, y + 1)]);
      visit(x, y - 1, !cut_[i]);
    }
  }

  void Relabel(int label) {
    std::vector<int> cells = std::move(cells_[label]);
    cells_[label].clear();
    for (int i : cells) label_[i] = kPending;
    bool first = true;
    for (int i : cells) {
      if (label_[i] != kPending) continue;
      int to = label;
      if (!first) {
        cells_.emplace_back();
        to = static_cast<int>(cells_.size()) - 1;
      }
      first = false;
      Flood(i, kPending, to);
    }
  }

  static constexpr int kPending = -2;
  const std::vector<std::uint8_t>& mask_;  // The cells to label.
  int w_, h_;
  std::vector<int> label_;
  std::vector<std::uint8_t> cut_;        // cut_[Index(x, y)]: (x, y - 1) and (x, y) not adjacent.
  std::vector<std::vector<int>> cells_;  // The cells of each label.
};

void CheckSizes(int w, int h, const std::vector<std::uint8_t>& cells, const std::vector<double>& xs,
                const std::vector<double>& ys) {
  if (w < 0 || h < 0 || cells.size() != static_cast<size_t>(w) * h ||
      xs.size() != static_cast<size_t>(w) + 1 || ys.size() != static_cast<size_t>(h) + 1) {
    throw std::invalid_argument("TraceCells(): grid sizes do not match");
  }
}

}  // namespace

std::vector<acd::Polygon2d> TraceCells(int w, int h, const std::vector<std::uint8_t>& blocked,
                                       const std::vector<double>& xs,
                                       const std::vector<double>& ys) {
  CheckSizes(w, h, blocked, xs, ys);
  Tracer tracer(w, h, blocked);
  tracer.CutPinches();
  return tracer.Trace(xs, ys, /*chamfer=*/0.0);
}

std::vector<acd::Polygon2d> TraceChamfered(int w, int h, const std::vector<std::uint8_t>& cells,
                                           const std::vector<double>& xs,
                                           const std::vector<double>& ys, double chamfer) {
  CheckSizes(w, h, cells, xs, ys);
  return Tracer(w, h, cells).Trace(xs, ys, chamfer);
}

}  // namespace acdplan::envs::internal
