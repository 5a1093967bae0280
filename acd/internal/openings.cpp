#include "acd/internal/openings.h"

#include <algorithm>
#include <cmath>

#include "acd/internal/rounding_noise.h"

namespace acdplan::acd::internal {
namespace {

struct Interval {
  double t0, t1;
  int component;
};

// The bounding box of a ring.
struct Box {
  Point2d min, max;
};
Box BoxOf(const Ring2d& ring) {
  Box box{ring.front(), ring.front()};
  for (const Point2d& p : ring) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

// The parameter intervals, along cut `from` -> `to`, of outer edges of components
// [first, last) that lie on the cut, into `intervals`. `boxes`: the components' outer boxes;
// one that keeps clear of the cut by more than the tolerance has no edge on it.
void IntervalsOnCut(const Decomposition2d& d, const std::vector<Box>& boxes, const Cut2d& cut,
                    int first, int last, std::vector<Interval>* intervals) {
  intervals->clear();
  const Point2d axis = cut.to - cut.from;
  const double length = axis.norm();
  if (length == 0.0) return;
  const Point2d unit = axis / length;
  // An edge lies on the cut when its ends do to within rounding: the cut's own ends, and points
  // later cuts constructed on it, are off its line by a few ulps of the coordinates. Not more: a
  // later cut from one end to a point 1e-8 beside the other (fuzz_decompose2d) runs 1e-3 rad
  // off this one, and its piece, which touches this cut at that end alone, was paired across it.
  const double scale = std::max({length, MaxAbs(cut.from), MaxAbs(cut.to)});
  const double tolerance = kRoundingNoise * scale;
  const Point2d pad = Point2d::Constant(2.0 * tolerance);
  const Point2d cut_min = cut.from.cwiseMin(cut.to) - pad;
  const Point2d cut_max = cut.from.cwiseMax(cut.to) + pad;
  for (int c = first; c < last; ++c) {
    const Box& box = boxes[c];
    if ((box.min.array() > cut_max.array()).any() || (box.max.array() < cut_min.array()).any()) {
      continue;
    }
    const Ring2d& ring = d.components[c].polygon.outer;
    const size_t n = ring.size();
    // Each vertex's offset from the cut's line is computed once, for both of its edges.
    auto offset = [&unit](const Point2d& v) { return unit.x() * v.y() - unit.y() * v.x(); };
    Point2d next = ring[0] - cut.from;
    double off_next = offset(next);
    for (size_t i = 0; i < n; ++i) {  // Edge u -> w, relative to the cut's start.
      const Point2d u = next;
      const bool u_on_line = std::abs(off_next) <= tolerance;
      const Point2d w = next = ring[i + 1 == n ? 0 : i + 1] - cut.from;
      off_next = offset(w);
      if (!u_on_line || std::abs(off_next) > tolerance) continue;
      double t0 = u.dot(unit) / length, t1 = w.dot(unit) / length;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0);
      t1 = std::min(t1, 1.0);
      if ((t1 - t0) * length > tolerance) intervals->push_back({t0, t1, c});
    }
  }
  std::sort(intervals->begin(), intervals->end(),
            [](const Interval& a, const Interval& b) { return a.t0 < b.t0; });
}

// First and one-past-last component index of the leaves below `node` (leaves are numbered in
// depth-first order, so they are contiguous).
std::pair<int, int> LeafRange(const Decomposition2d& d, int node) {
  int lo = node, hi = node;
  while (d.tree[lo].children[0] >= 0) lo = d.tree[lo].children[0];
  while (d.tree[hi].children[1] >= 0) hi = d.tree[hi].children[1];
  return {d.tree[lo].component, d.tree[hi].component + 1};
}

}  // namespace

std::vector<Opening2d> FindOpenings(const Decomposition2d& d) {
  std::vector<Opening2d> openings;
  std::vector<Box> boxes;
  boxes.reserve(d.components.size());
  for (const Component2d& c : d.components) boxes.push_back(BoxOf(c.polygon.outer));
  std::vector<Interval> left, right;  // Per cut; kept for their capacity.
  std::vector<Opening2d> found;
  for (int id = 0; id < static_cast<int>(d.tree.size()); ++id) {
    const HierarchyNode2d& node = d.tree[id];
    if (node.children[0] < 0) continue;
    const auto [a0, a1] = LeafRange(d, node.children[0]);
    const auto [b0, b1] = LeafRange(d, node.children[1]);
    for (const Cut2d& cut : node.cuts) {
      IntervalsOnCut(d, boxes, cut, a0, a1, &left);
      IntervalsOnCut(d, boxes, cut, b0, b1, &right);
      const double length = (cut.to - cut.from).norm();
      const double tolerance = 1e-9 * std::max(1.0, length);
      found.clear();
      double last_t1 = 0.0;
      for (const Interval& l : left) {
        for (const Interval& r : right) {
          const double t0 = std::max(l.t0, r.t0), t1 = std::min(l.t1, r.t1);
          if ((t1 - t0) * length <= tolerance) continue;
          const int ca = std::min(l.component, r.component);
          const int cb = std::max(l.component, r.component);
          // Merge with the previous piece of this cut when it continues it.
          if (!found.empty() && found.back().component_a == ca && found.back().component_b == cb &&
              std::abs(t0 - last_t1) * length <= tolerance) {
            found.back().b = cut.from + t1 * (cut.to - cut.from);
          } else {
            found.push_back(
                {cut.from + t0 * (cut.to - cut.from), cut.from + t1 * (cut.to - cut.from), ca, cb});
          }
          last_t1 = t1;
        }
      }
      openings.insert(openings.end(), found.begin(), found.end());
    }
  }
  return openings;
}

}  // namespace acdplan::acd::internal
