#include "acd/internal/openings.h"

#include <algorithm>
#include <cmath>

#include "acd/internal/rounding_noise.h"
#include "acd/internal/thread_scratch.h"

namespace acdplan::acd::internal {
namespace {

struct Interval {
  double t0, t1;
  int component;
};

// A cut as a parameter line: t = 0 at `from`, 1 at `to`.
struct CutFrame {
  Point2d from, unit;
  double length, tolerance;
};

CutFrame FrameOf(const Cut2d& cut) {
  const Point2d axis = cut.to - cut.from;
  const double length = axis.norm();
  // The cut's own ends, and points later cuts constructed on it, are off its line by a few ulps
  // of the coordinates: intervals shorter than that are no part of it.
  const double scale = std::max({length, MaxAbs(cut.from), MaxAbs(cut.to)});
  return {cut.from, length > 0.0 ? Point2d(axis / length) : Point2d::Zero(), length,
          kRoundingNoise * scale};
}

// The parameter interval of edge u -> w, which lies on the cut, clipped to the cut; false if
// nothing of it is left.
bool IntervalOf(const CutFrame& frame, const Point2d& u, const Point2d& w, Interval* interval) {
  if (frame.length == 0.0) return false;
  double t0 = (u - frame.from).dot(frame.unit) / frame.length;
  double t1 = (w - frame.from).dot(frame.unit) / frame.length;
  if (t0 > t1) std::swap(t0, t1);
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, 1.0);
  interval->t0 = t0;
  interval->t1 = t1;
  return (t1 - t0) * frame.length > frame.tolerance;
}

// FindOpenings()'s working storage.
struct FindScratch {
  std::vector<int> first_cut, begin, end;
  std::vector<CutFrame> frames;
  std::vector<Interval> intervals, left, right;

  size_t HeldBytes() const {
    return (first_cut.capacity() + begin.capacity() + end.capacity()) * sizeof(int) +
           frames.capacity() * sizeof(CutFrame) +
           (intervals.capacity() + left.capacity() + right.capacity()) * sizeof(Interval);
  }
  void Release() { *this = FindScratch(); }
};

// First and one-past-last component index of the leaves below `node` (leaves are numbered in
// depth-first order, so they are contiguous).
std::pair<int, int> LeafRange(const Decomposition2d& d, int node) {
  int lo = node, hi = node;
  while (d.tree[lo].children[0] >= 0) lo = d.tree[lo].children[0];
  while (d.tree[hi].children[1] >= 0) hi = d.tree[hi].children[1];
  return {d.tree[lo].component, d.tree[hi].component + 1};
}

}  // namespace

std::vector<Opening2d> FindOpenings(const Decomposition2d& d, const std::vector<CutEdge>& cut_edges,
                                    const std::vector<int>& first) {
  // The working storage, kept per thread: one call per decomposition, but a small one would
  // spend a good part of its time allocating it.
  thread_local FindScratch scratch;
  const ScratchScope scope(scratch);
  // The cuts in node order, node `id`'s from first_cut[id] on.
  std::vector<int>& first_cut = scratch.first_cut;
  std::vector<CutFrame>& frames = scratch.frames;
  first_cut.assign(d.tree.size() + 1, 0);
  frames.clear();
  for (size_t id = 0; id < d.tree.size(); ++id) {
    first_cut[id + 1] = first_cut[id] + static_cast<int>(d.tree[id].cuts.size());
    for (const Cut2d& cut : d.tree[id].cuts) frames.push_back(FrameOf(cut));
  }
  // The intervals of the leaf edges on each cut, in component and edge order; those of cut k
  // from begin[k] to end[k] (counted first, then filled).
  std::vector<int>& begin = scratch.begin;
  std::vector<int>& end = scratch.end;
  std::vector<Interval>& intervals = scratch.intervals;
  begin.assign(frames.size() + 1, 0);
  for (const CutEdge& e : cut_edges) ++begin[first_cut[e.node] + e.cut + 1];
  for (size_t k = 0; k < frames.size(); ++k) begin[k + 1] += begin[k];
  end.assign(begin.begin(), begin.end() - 1);
  intervals.resize(begin.back());
  for (int c = 0; c < static_cast<int>(d.components.size()); ++c) {
    const Ring2d& ring = d.components[c].polygon.outer;
    const int n = static_cast<int>(ring.size());
    for (int j = first[c]; j < first[c + 1]; ++j) {
      const CutEdge& e = cut_edges[j];
      const int k = first_cut[e.node] + e.cut;
      Interval& interval = intervals[end[k]];
      if (IntervalOf(frames[k], ring[e.edge], ring[e.edge + 1 == n ? 0 : e.edge + 1], &interval)) {
        interval.component = c;
        ++end[k];
      }
    }
  }
  std::vector<Opening2d> openings;
  std::vector<Interval>& left = scratch.left;
  std::vector<Interval>& right = scratch.right;
  auto by_start = [](const Interval& a, const Interval& b) { return a.t0 < b.t0; };
  for (int id = 0; id < static_cast<int>(d.tree.size()); ++id) {
    const HierarchyNode2d& node = d.tree[id];
    if (node.children[0] < 0) continue;
    const auto [a0, a1] = LeafRange(d, node.children[0]);
    for (int k = first_cut[id]; k < first_cut[id + 1]; ++k) {
      left.clear();
      right.clear();
      for (int j = begin[k]; j < end[k]; ++j) {
        const Interval& interval = intervals[j];
        (a0 <= interval.component && interval.component < a1 ? left : right).push_back(interval);
      }
      std::sort(left.begin(), left.end(), by_start);
      std::sort(right.begin(), right.end(), by_start);
      const Cut2d& cut = node.cuts[k - first_cut[id]];
      const double length = frames[k].length;
      const double tolerance = 1e-9 * std::max(1.0, length);
      const size_t first_found = openings.size();  // This cut's openings from here on.
      double last_t1 = 0.0;
      for (const Interval& l : left) {
        for (const Interval& r : right) {
          const double t0 = std::max(l.t0, r.t0), t1 = std::min(l.t1, r.t1);
          if ((t1 - t0) * length <= tolerance) continue;
          const int ca = std::min(l.component, r.component);
          const int cb = std::max(l.component, r.component);
          // Merge with the previous piece of this cut when it continues it.
          if (openings.size() > first_found && openings.back().component_a == ca &&
              openings.back().component_b == cb && std::abs(t0 - last_t1) * length <= tolerance) {
            openings.back().b = cut.from + t1 * (cut.to - cut.from);
          } else {
            openings.push_back(
                {cut.from + t0 * (cut.to - cut.from), cut.from + t1 * (cut.to - cut.from), ca, cb});
          }
          last_t1 = t1;
        }
      }
    }
  }
  return openings;
}

}  // namespace acdplan::acd::internal
