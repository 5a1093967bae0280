#pragma once
// Axis-aligned box overlap reporting by sort and sweep, used by CheckDecomposition() and
// ComputeOpenings(). Internal.

#include <algorithm>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// A closed axis-aligned box with a caller-chosen id.
struct IdBox {
  double lo[2], hi[2];
  int id;
};

/// The box of the segment a-b, grown by `grow` on every side.
inline IdBox SegmentBox(const Point2d& a, const Point2d& b, int id, double grow = 0.0) {
  return {{std::min(a.x(), b.x()) - grow, std::min(a.y(), b.y()) - grow},
          {std::max(a.x(), b.x()) + grow, std::max(a.y(), b.y()) + grow},
          id};
}

namespace box_sweep_detail {

// The axis to sweep along: the one where boxes are short relative to the spread of their
// positions, so fewer boxes are active at once.
inline int SweepAxis(const std::vector<IdBox>& a, const std::vector<IdBox>& b) {
  double extent[2] = {0.0, 0.0}, lo[2] = {0.0, 0.0}, hi[2] = {0.0, 0.0};
  bool first = true;
  for (const std::vector<IdBox>* boxes : {&a, &b}) {
    for (const IdBox& box : *boxes) {
      for (int d = 0; d < 2; ++d) {
        extent[d] += box.hi[d] - box.lo[d];
        lo[d] = first ? box.lo[d] : std::min(lo[d], box.lo[d]);
        hi[d] = first ? box.hi[d] : std::max(hi[d], box.hi[d]);
      }
      first = false;
    }
  }
  // Compare extent[0] / range[0] with extent[1] / range[1] without dividing by zero.
  return extent[0] * (hi[1] - lo[1]) <= extent[1] * (hi[0] - lo[0]) ? 0 : 1;
}

inline void SortAlong(std::vector<IdBox>* boxes, int axis) {
  std::sort(boxes->begin(), boxes->end(), [axis](const IdBox& x, const IdBox& y) {
    return x.lo[axis] != y.lo[axis] ? x.lo[axis] < y.lo[axis] : x.id < y.id;
  });
}

}  // namespace box_sweep_detail

/// Calls `report(a_id, b_id)` once for every box of `a` and box of `b` that overlap (closed
/// boxes: touching counts). Deterministic order. O((n + m) log(n + m) + n k), k the number of
/// boxes active at a time along the sweep axis (small for the edges of a plane subdivision).
template <class Report>
void ForEachOverlap(std::vector<IdBox> a, std::vector<IdBox> b, Report report) {
  using namespace box_sweep_detail;
  const int axis = SweepAxis(a, b), other = 1 - axis;
  SortAlong(&a, axis);
  SortAlong(&b, axis);
  // Active boxes are kept by value: the scan is the hot loop and stays in cache.
  std::vector<IdBox> active_a, active_b;
  size_t i = 0, j = 0;
  auto scan = [&](const IdBox& box, std::vector<IdBox>* active, bool box_is_a) {
    for (size_t k = 0; k < active->size();) {
      const IdBox& other_box = (*active)[k];
      if (other_box.hi[axis] < box.lo[axis]) {  // Ended before this one starts: retire it.
        (*active)[k] = active->back();
        active->pop_back();
        continue;
      }
      if (other_box.lo[other] <= box.hi[other] && box.lo[other] <= other_box.hi[other]) {
        if (box_is_a) {
          report(box.id, other_box.id);
        } else {
          report(other_box.id, box.id);
        }
      }
      ++k;
    }
  };
  while (i < a.size() || j < b.size()) {
    const bool take_a = j == b.size() || (i < a.size() && a[i].lo[axis] <= b[j].lo[axis]);
    if (take_a) {
      scan(a[i], &active_b, true);
      active_a.push_back(a[i++]);
    } else {
      scan(b[j], &active_a, false);
      active_b.push_back(b[j++]);
    }
  }
}

/// Calls `report(id1, id2)` once for every unordered pair of overlapping boxes in `boxes`.
template <class Report>
void ForEachSelfOverlap(std::vector<IdBox> boxes, Report report) {
  using namespace box_sweep_detail;
  const int axis = SweepAxis(boxes, {}), other = 1 - axis;
  SortAlong(&boxes, axis);
  std::vector<IdBox> active;
  for (const IdBox& box : boxes) {
    for (size_t k = 0; k < active.size();) {
      const IdBox& other_box = active[k];
      if (other_box.hi[axis] < box.lo[axis]) {
        active[k] = active.back();
        active.pop_back();
        continue;
      }
      if (other_box.lo[other] <= box.hi[other] && box.lo[other] <= other_box.hi[other]) {
        report(other_box.id, box.id);
      }
      ++k;
    }
    active.push_back(box);
  }
}

}  // namespace acdplan::acd::internal
