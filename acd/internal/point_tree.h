#pragma once
// A k-d tree over points for exact nearest-point searches. Internal.

#include <cmath>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// A static k-d tree over a set of points (ids are their positions in the input). A search
/// visits the points of every node whose box may lie within a radius of the query, nearest
/// node first, and the visitor may shrink the radius as it goes; the visitor decides (and
/// breaks ties) itself, so a search returns exactly what a scan of all points would.
/// Building is O(n log n); a nearest-point search is about O(log n) on ordinary point sets.
class PointTree {
 public:
  explicit PointTree(const std::vector<Point2d>& points);

  /// Calls `visit(id, d2)`, d2 = (point - p).squaredNorm(), for every point that can lie
  /// within `*radius` of `p`: a node is skipped only when sqrt(d2) > *radius is certain for
  /// every point in it (the box distance is computed with the same roundings, which are
  /// monotone, so it never exceeds a point's d2). `visit` may lower `*radius`.
  template <typename Visit>
  void Search(const Point2d& p, double* radius, Visit visit) const {
    if (!nodes_.empty()) Search(0, p, radius, visit);
  }

 private:
  struct Node {
    Point2d lower, upper;  // Bounding box of the node's points.
    int begin, end;        // Range in entries_.
    int left = -1, right = -1;
  };
  int Build(int begin, int end);
  double BoxDistance2(int node, const Point2d& p) const;
  template <typename Visit>
  void Search(int node, const Point2d& p, double* radius, Visit& visit) const;

  struct Entry {
    Point2d point;
    int id;
  };
  std::vector<Entry> entries_;  // The points, reordered so that each node is a range.
  std::vector<Node> nodes_;
};

inline double PointTree::BoxDistance2(int node, const Point2d& p) const {
  const Node& n = nodes_[node];
  const double dx =
      p.x() < n.lower.x() ? n.lower.x() - p.x() : (p.x() > n.upper.x() ? p.x() - n.upper.x() : 0.0);
  const double dy =
      p.y() < n.lower.y() ? n.lower.y() - p.y() : (p.y() > n.upper.y() ? p.y() - n.upper.y() : 0.0);
  return dx * dx + dy * dy;
}

template <typename Visit>
void PointTree::Search(int node, const Point2d& p, double* radius, Visit& visit) const {
  if (std::sqrt(BoxDistance2(node, p)) > *radius) return;
  const Node& n = nodes_[node];
  if (n.left < 0) {
    for (int k = n.begin; k < n.end; ++k)
      visit(entries_[k].id, (entries_[k].point - p).squaredNorm());
    return;
  }
  const bool left_first = BoxDistance2(n.left, p) <= BoxDistance2(n.right, p);
  Search(left_first ? n.left : n.right, p, radius, visit);
  Search(left_first ? n.right : n.left, p, radius, visit);
}

}  // namespace acdplan::acd::internal
