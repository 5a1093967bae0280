#pragma once
// Axis-aligned box overlap reporting by sort and sweep, used by CheckDecomposition() and
// ComputeOpenings(). Internal.

#include <algorithm>
#include <cmath>
#include <limits>
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

/// The box of the vertices of `ring` (empty, lo > hi, for an empty ring).
inline IdBox RingBox(const Ring2d& ring, int id) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  IdBox box{{kInf, kInf}, {-kInf, -kInf}, id};
  for (const Point2d& p : ring) {
    for (int d = 0; d < 2; ++d) {
      box.lo[d] = std::min(box.lo[d], p[d]);
      box.hi[d] = std::max(box.hi[d], p[d]);
    }
  }
  return box;
}

/// Whether box `inner` lies within box `outer` (closed boxes).
inline bool BoxWithin(const IdBox& inner, const IdBox& outer) {
  return inner.lo[0] >= outer.lo[0] && inner.hi[0] <= outer.hi[0] && inner.lo[1] >= outer.lo[1] &&
         inner.hi[1] <= outer.hi[1];
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

// Strips across the sweep axis, each swept on its own. A single sweep keeps every box that
// spans the sweep line active, about sqrt(n) of them where boxes fill the plane (a map of
// buildings, a grid world), and tests each new box against them all: O(n^1.5). In strips that
// share the boxes out evenly along the other axis, a box meets only the active boxes of its own
// strips. A pair is reported only in the strip that holds the lower end of their overlap along
// the other axis, so once.
class Strips {
 public:
  Strips(const std::vector<IdBox>& a, const std::vector<IdBox>& b, int other) {
    const size_t n = a.size() + b.size();
    constexpr size_t kSingleSweep = 512;  // Below this, one sweep costs too little to split.
    if (n < kSingleSweep) return;
    std::vector<double> middles;
    middles.reserve(n);
    for (const std::vector<IdBox>* boxes : {&a, &b}) {
      for (const IdBox& box : *boxes) middles.push_back(0.5 * (box.lo[other] + box.hi[other]));
    }
    std::sort(middles.begin(), middles.end());
    // Boundaries at quantiles of the boxes' middles, as many strips as about sqrt(n) / 4, fewer
    // while boxes that span several strips would make the strips' boxes more than 2n in all
    // (long boxes, as the edges of a star, gain nothing from strips).
    for (size_t count = static_cast<size_t>(std::sqrt(static_cast<double>(n)) / 4.0); count > 1;
         count /= 2) {
      bounds_.clear();
      for (size_t k = 1; k < count; ++k) {
        const double bound = middles[k * n / count];
        if (bounds_.empty() || bound > bounds_.back()) bounds_.push_back(bound);
      }
      size_t placed = 0;
      for (const std::vector<IdBox>* boxes : {&a, &b}) {
        for (const IdBox& box : *boxes) placed += Of(box.hi[other]) - Of(box.lo[other]) + 1;
      }
      if (placed <= 2 * n) return;
    }
    bounds_.clear();
  }

  size_t Count() const { return bounds_.size() + 1; }
  /// The strip that holds coordinate v along the other axis.
  size_t Of(double v) const {
    return static_cast<size_t>(std::upper_bound(bounds_.begin(), bounds_.end(), v) -
                               bounds_.begin());
  }

  /// `boxes` by strip, each box in every strip it spans.
  std::vector<std::vector<IdBox>> Split(const std::vector<IdBox>& boxes, int other) const {
    std::vector<std::vector<IdBox>> split(Count());
    for (const IdBox& box : boxes) {
      for (size_t s = Of(box.lo[other]), last = Of(box.hi[other]); s <= last; ++s) {
        split[s].push_back(box);
      }
    }
    return split;
  }

 private:
  std::vector<double> bounds_;  // Between strips, increasing.
};

// ForEachOverlap() of one strip, or of all boxes.
template <class Report>
void SweepPairs(std::vector<IdBox> a, std::vector<IdBox> b, int axis, Report report) {
  const int other = 1 - axis;
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
          report(box, other_box);
        } else {
          report(other_box, box);
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

// ForEachSelfOverlap() of one strip, or of all boxes.
template <class Report>
void SweepSelfPairs(std::vector<IdBox> boxes, int axis, Report report) {
  const int other = 1 - axis;
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
        report(other_box, box);
      }
      ++k;
    }
    active.push_back(box);
  }
}

}  // namespace box_sweep_detail

/// Calls `report(a_id, b_id)` once for every box of `a` and box of `b` that overlap (closed
/// boxes: touching counts). Deterministic order. A sweep along one axis in strips across it:
/// O(n log n + n k), k the number of boxes of a strip active at a time (small for the edges of a
/// plane subdivision, or boxes spread over the plane).
template <class Report>
void ForEachOverlap(std::vector<IdBox> a, std::vector<IdBox> b, Report report) {
  using namespace box_sweep_detail;
  const int axis = SweepAxis(a, b), other = 1 - axis;
  const Strips strips(a, b, other);
  if (strips.Count() == 1) {
    SweepPairs(std::move(a), std::move(b), axis,
               [&](const IdBox& x, const IdBox& y) { report(x.id, y.id); });
    return;
  }
  std::vector<std::vector<IdBox>> a_split = strips.Split(a, other),
                                  b_split = strips.Split(b, other);
  for (size_t s = 0; s < strips.Count(); ++s) {
    SweepPairs(std::move(a_split[s]), std::move(b_split[s]), axis,
               [&](const IdBox& x, const IdBox& y) {
                 if (strips.Of(std::max(x.lo[other], y.lo[other])) == s) report(x.id, y.id);
               });
  }
}

/// Calls `report(id1, id2)` once for every unordered pair of overlapping boxes in `boxes`, as
/// ForEachOverlap().
template <class Report>
void ForEachSelfOverlap(std::vector<IdBox> boxes, Report report) {
  using namespace box_sweep_detail;
  const int axis = SweepAxis(boxes, {}), other = 1 - axis;
  const Strips strips(boxes, {}, other);
  if (strips.Count() == 1) {
    SweepSelfPairs(std::move(boxes), axis,
                   [&](const IdBox& x, const IdBox& y) { report(x.id, y.id); });
    return;
  }
  std::vector<std::vector<IdBox>> split = strips.Split(boxes, other);
  for (size_t s = 0; s < strips.Count(); ++s) {
    SweepSelfPairs(std::move(split[s]), axis, [&](const IdBox& x, const IdBox& y) {
      if (strips.Of(std::max(x.lo[other], y.lo[other])) == s) report(x.id, y.id);
    });
  }
}

}  // namespace acdplan::acd::internal
