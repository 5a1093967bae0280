#pragma once
// A bounding-box tree over points for exact nearest-point searches. Internal.

#include <cmath>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// A static bounding-box tree over points (ids are their positions in the input). The points
/// are taken in runs of a few consecutive ones, which on a ring lie close together, so that
/// building costs O(n) plus a k-d split of n / 16 runs. A search visits the points of every run
/// whose box may lie within a radius of the query, nearest node first, and the visitor may
/// shrink the radius as it goes; the visitor decides (and breaks ties) itself, so a search
/// returns exactly what a scan of all points would, whatever the order of visits.
class PointTree {
 public:
  /// `ring_begin`: the positions where a ring starts (runs never span two rings); may be empty.
  explicit PointTree(std::vector<Point2d> points, const std::vector<int>& ring_begin = {});

  /// Calls `visit(id, d2)`, d2 = (point - p).squaredNorm(), for every point that can lie
  /// within `*radius` of `p`: a box is skipped only when sqrt(d2) > *radius is certain for
  /// every point in it (the box distance is computed with the same roundings, which are
  /// monotone, so it never exceeds a point's d2). `visit` may lower `*radius`.
  template <typename Visit>
  void Search(const Point2d& p, double* radius, Visit visit) const {
    if (!nodes_.empty()) Search(0, p, radius, visit);
  }

 private:
  struct Box {
    Point2d lower, upper;
  };
  struct Run {
    Box box;
    int begin, end;  // Range in points_.
  };
  struct Node {
    Box box;
    int begin, end;  // Range in runs_.
    int left = -1, right = -1;
  };
  int Build(int begin, int end);
  static double BoxDistance2(const Box& box, const Point2d& p);
  template <typename Visit>
  void Search(int node, const Point2d& p, double* radius, Visit& visit) const;

  std::vector<Point2d> points_;
  std::vector<Run> runs_;  // Reordered so that each node is a range.
  std::vector<Node> nodes_;
};

inline double PointTree::BoxDistance2(const Box& box, const Point2d& p) {
  const double dx = p.x() < box.lower.x() ? box.lower.x() - p.x()
                                          : (p.x() > box.upper.x() ? p.x() - box.upper.x() : 0.0);
  const double dy = p.y() < box.lower.y() ? box.lower.y() - p.y()
                                          : (p.y() > box.upper.y() ? p.y() - box.upper.y() : 0.0);
  return dx * dx + dy * dy;
}

template <typename Visit>
void PointTree::Search(int node, const Point2d& p, double* radius, Visit& visit) const {
  const Node& n = nodes_[node];
  if (std::sqrt(BoxDistance2(n.box, p)) > *radius) return;
  if (n.left < 0) {
    for (int r = n.begin; r < n.end; ++r) {
      const Run& run = runs_[r];
      if (std::sqrt(BoxDistance2(run.box, p)) > *radius) continue;
      for (int k = run.begin; k < run.end; ++k) visit(k, (points_[k] - p).squaredNorm());
    }
    return;
  }
  const bool left_first =
      BoxDistance2(nodes_[n.left].box, p) <= BoxDistance2(nodes_[n.right].box, p);
  Search(left_first ? n.left : n.right, p, radius, visit);
  Search(left_first ? n.right : n.left, p, radius, visit);
}

}  // namespace acdplan::acd::internal
