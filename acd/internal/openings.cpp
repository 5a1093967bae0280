#include "acd/internal/openings.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "acd/internal/box_sweep.h"
#include "acd/internal/exact_predicates.h"
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

// Calls `edge(a, b)` for every edge a -> b of the rings of `polygon`, outer ring first.
template <typename Edge>
void ForEachRingEdge(const Polygon2d& polygon, Edge edge) {
  for (size_t r = 0; r <= polygon.holes.size(); ++r) {
    const Ring2d& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
    for (size_t i = 0; i < ring.size(); ++i) edge(ring[i], ring[i + 1 == ring.size() ? 0 : i + 1]);
  }
}

}  // namespace

std::vector<Seam> FindSeams(const std::vector<Polygon2d>& polygons) {
  if (polygons.size() < 2) return {};
  struct Edge {
    Point2d a, b;
    int polygon;
  };
  std::vector<Edge> edges;
  edges.reserve(static_cast<size_t>(std::accumulate(
      polygons.begin(), polygons.end(), 0,
      [](int sum, const Polygon2d& polygon) { return sum + VertexCount(polygon); })));
  for (int p = 0; p < static_cast<int>(polygons.size()); ++p) {
    ForEachRingEdge(polygons[p], [&](const Point2d& a, const Point2d& b) {
      edges.push_back({a, b, p});
    });
  }
  struct Found {
    int a, b;  // Into `edges`, a the lower.
    Cut2d segment;
  };
  std::vector<Found> found;
  auto test = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    const Edge& e = edges[i];
    const Edge& f = edges[j];
    if (e.polygon == f.polygon) return;
    if (Orientation(e.a, e.b, f.a) != 0 || Orientation(e.a, e.b, f.b) != 0) return;
    const Point2d along = e.b - e.a;
    if (along.dot(f.b - f.a) >= 0.0) return;  // Both one way: overlapping polygons, no seam.
    // The overlap in e's direction: from the later of e's start and f's end to the earlier of
    // e's end and f's start (points of the rings, told apart by their projections).
    auto t = [&](const Point2d& q) { return (q - e.a).dot(along); };
    const Point2d& from = t(f.b) > 0.0 ? f.b : e.a;
    const Point2d& to = t(f.a) < t(e.b) ? f.a : e.b;
    if (t(from) < t(to)) found.push_back({i, j, {from, to}});
  };
  // Axis-parallel edges meet only edges on their own line: sorted by it and swept along it (in
  // a box sweep, each would stay active across a grid world's rows). The others by a box sweep.
  struct OnLine {
    double coordinate, lo;  // The line (y of a horizontal edge, x of a vertical one), and where
                            // the edge starts along it.
    int edge;
  };
  std::vector<OnLine> on_line[2];  // Horizontal, vertical.
  std::vector<IdBox> slanted;
  for (int i = 0; i < static_cast<int>(edges.size()); ++i) {
    const Edge& e = edges[i];
    const int axis = e.a.y() == e.b.y() ? 0 : e.a.x() == e.b.x() ? 1 : -1;
    if (axis < 0) {
      slanted.push_back(SegmentBox(e.a, e.b, i));
    } else {
      on_line[axis].push_back({e.a[1 - axis], std::min(e.a[axis], e.b[axis]), i});
    }
  }
  std::vector<std::pair<double, int>> active;  // Where each edge of the line so far ends.
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<OnLine>& list = on_line[axis];
    std::sort(list.begin(), list.end(), [](const OnLine& x, const OnLine& y) {
      if (x.coordinate != y.coordinate) return x.coordinate < y.coordinate;
      return x.lo != y.lo ? x.lo < y.lo : x.edge < y.edge;
    });
    for (size_t k = 0; k < list.size(); ++k) {
      const OnLine& e = list[k];
      if (k == 0 || e.coordinate != list[k - 1].coordinate) active.clear();
      active.erase(std::remove_if(active.begin(), active.end(),
                                  [&](const std::pair<double, int>& o) { return o.first <= e.lo; }),
                   active.end());
      for (const auto& other : active) test(other.second, e.edge);
      const Edge& edge = edges[static_cast<size_t>(e.edge)];
      active.emplace_back(std::max(edge.a[axis], edge.b[axis]), e.edge);
    }
  }
  ForEachSelfOverlap(std::move(slanted), test);
  std::sort(found.begin(), found.end(),
            [](const Found& x, const Found& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  std::vector<Seam> seams;
  seams.reserve(found.size());
  for (const Found& f : found) seams.push_back({f.segment, edges[f.a].polygon, edges[f.b].polygon});
  return seams;
}

std::vector<Opening2d> FindOpenings(const Decomposition2d& d, const std::vector<CutEdge>& cut_edges,
                                    const std::vector<int>& first, const std::vector<Seam>& seams) {
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
  // The openings along `cut` (frame `frame`) from the intervals [on_cut, on_cut_end) of leaf
  // edges on it, between the components on its two sides.
  auto pair_up = [&](const CutFrame& frame, const Cut2d& cut, const Interval* on_cut,
                     const Interval* on_cut_end, auto on_left) {
    left.clear();
    right.clear();
    for (const Interval* interval = on_cut; interval != on_cut_end; ++interval) {
      (on_left(interval->component) ? left : right).push_back(*interval);
    }
    std::sort(left.begin(), left.end(), by_start);
    std::sort(right.begin(), right.end(), by_start);
    const double length = frame.length;
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
  };
  for (int id = 0; id < static_cast<int>(d.tree.size()); ++id) {
    const HierarchyNode2d& node = d.tree[id];
    if (node.children[0] < 0) continue;
    // (Not a structured binding: the lambda below captures them, which C++17 does not allow.)
    const std::pair<int, int> leaves = LeafRange(d, node.children[0]);
    const int a0 = leaves.first, a1 = leaves.second;
    for (int k = first_cut[id]; k < first_cut[id + 1]; ++k) {
      pair_up(frames[k], node.cuts[k - first_cut[id]], intervals.data() + begin[k],
              intervals.data() + end[k], [&](int c) { return a0 <= c && c < a1; });
    }
  }
  if (seams.empty()) return openings;
  // The leaf edges on seams, outer and hole rings alike (the hierarchy does not follow input
  // edges), by a sweep of the seams' boxes, widened by their tolerance, against the edges'.
  // An edge lies on a seam when both its ends lie within the tolerance of the seam's line.
  std::vector<CutFrame> seam_frames;
  std::vector<IdBox> seam_boxes, edge_boxes;
  for (int k = 0; k < static_cast<int>(seams.size()); ++k) {
    seam_frames.push_back(FrameOf(seams[k].segment));
    seam_boxes.push_back(
        SegmentBox(seams[k].segment.from, seams[k].segment.to, k, seam_frames.back().tolerance));
  }
  struct LeafEdge {
    Point2d a, b;
    int component;
  };
  std::vector<LeafEdge> leaf_edges;
  for (int c = 0; c < static_cast<int>(d.components.size()); ++c) {
    ForEachRingEdge(d.components[c].polygon, [&](const Point2d& a, const Point2d& b) {
      edge_boxes.push_back(SegmentBox(a, b, static_cast<int>(leaf_edges.size())));
      leaf_edges.push_back({a, b, c});
    });
  }
  std::vector<std::vector<Interval>> on_seam(seams.size());
  ForEachOverlap(std::move(seam_boxes), std::move(edge_boxes), [&](int k, int e) {
    const CutFrame& frame = seam_frames[static_cast<size_t>(k)];
    const LeafEdge& edge = leaf_edges[static_cast<size_t>(e)];
    const int source = d.components[edge.component].source;
    if (source != seams[k].polygon_a && source != seams[k].polygon_b) return;
    auto off_line = [&](const Point2d& p) {
      const Point2d v = p - frame.from;
      return std::abs(v.x() * frame.unit.y() - v.y() * frame.unit.x());
    };
    Interval interval;
    if (off_line(edge.a) <= frame.tolerance && off_line(edge.b) <= frame.tolerance &&
        IntervalOf(frame, edge.a, edge.b, &interval)) {
      interval.component = edge.component;
      on_seam[static_cast<size_t>(k)].push_back(interval);
    }
  });
  for (int k = 0; k < static_cast<int>(seams.size()); ++k) {
    const std::vector<Interval>& list = on_seam[static_cast<size_t>(k)];
    const int polygon_a = seams[k].polygon_a;
    pair_up(seam_frames[static_cast<size_t>(k)], seams[k].segment, list.data(),
            list.data() + list.size(), [&](int c) { return d.components[c].source == polygon_a; });
  }
  return openings;
}

}  // namespace acdplan::acd::internal
