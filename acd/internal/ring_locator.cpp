#include "acd/internal/ring_locator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acd/internal/exact_predicates.h"

namespace acdplan::acd::internal {

double SegmentDistance(const Point2d& p, const Point2d& a, const Point2d& b) {
  const Point2d ab = b - a;
  const double length2 = ab.squaredNorm();
  double t = length2 > 0.0 ? (p - a).dot(ab) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

RingLocator::RingLocator(const Polygon2d& polygon) {
  auto add_ring = [this](const Ring2d& ring) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) edges_.push_back({ring[i], ring[(i + 1) % n]});
  };
  size_t total = polygon.outer.size();
  for (const Ring2d& hole : polygon.holes) total += hole.size();
  edges_.reserve(total);
  add_ring(polygon.outer);
  for (const Ring2d& hole : polygon.holes) add_ring(hole);
  if (edges_.empty()) return;

  y_min_ = x_min_ = std::numeric_limits<double>::infinity();
  y_max_ = x_max_ = -std::numeric_limits<double>::infinity();
  for (const Edge& e : edges_) {
    y_min_ = std::min({y_min_, e.a.y(), e.b.y()});
    y_max_ = std::max({y_max_, e.a.y(), e.b.y()});
    x_min_ = std::min({x_min_, e.a.x(), e.b.x()});
    x_max_ = std::max({x_max_, e.a.x(), e.b.x()});
  }
  // About four edges per slab; small rings get one slab (a plain scan).
  const int n = static_cast<int>(edges_.size());
  slab_count_ = std::clamp(n / 4, 1, 4096);
  const double height = y_max_ - y_min_;
  if (!(height > 0.0) || !std::isfinite(height)) slab_count_ = 1;
  inverse_height_ = slab_count_ > 1 ? slab_count_ / height : 0.0;

  std::vector<int> count(slab_count_ + 1, 0);
  for (const Edge& e : edges_) {
    const int lo = Slab(std::min(e.a.y(), e.b.y()));
    const int hi = Slab(std::max(e.a.y(), e.b.y()));
    for (int s = lo; s <= hi; ++s) ++count[s + 1];
  }
  for (int s = 0; s < slab_count_; ++s) count[s + 1] += count[s];
  slab_begin_ = count;
  slab_edges_.resize(count[slab_count_]);
  for (int i = 0; i < n; ++i) {
    const Edge& e = edges_[i];
    const int lo = Slab(std::min(e.a.y(), e.b.y()));
    const int hi = Slab(std::max(e.a.y(), e.b.y()));
    for (int s = lo; s <= hi; ++s) slab_edges_[count[s]++] = i;
  }
}

int RingLocator::Slab(double y) const {
  if (slab_count_ == 1) return 0;
  const double s = std::floor((y - y_min_) * inverse_height_);
  if (!(s > 0.0)) return 0;
  if (s >= slab_count_ - 1) return slab_count_ - 1;
  return static_cast<int>(s);
}

bool RingLocator::InsideParity(const Point2d& p) const {
  if (edges_.empty() || p.y() < y_min_ || p.y() > y_max_ || p.x() > x_max_) return false;
  const int s = Slab(p.y());
  bool inside = false;
  for (int k = slab_begin_[s]; k < slab_begin_[s + 1]; ++k) {
    const Edge& e = edges_[slab_edges_[k]];
    if (RayCrossesEdge(p, e.a, e.b)) inside = !inside;
  }
  return inside;
}

bool RingLocator::NearBoundary(const Point2d& p, double tolerance) const {
  if (edges_.empty() || p.y() < y_min_ - tolerance || p.y() > y_max_ + tolerance ||
      p.x() < x_min_ - tolerance || p.x() > x_max_ + tolerance) {
    return false;
  }
  const int lo = Slab(p.y() - tolerance);
  const int hi = Slab(p.y() + tolerance);
  for (int s = lo; s <= hi; ++s) {
    for (int k = slab_begin_[s]; k < slab_begin_[s + 1]; ++k) {
      const Edge& e = edges_[slab_edges_[k]];
      if (SegmentDistance(p, e.a, e.b) <= tolerance) return true;
    }
  }
  return false;
}

PointLocation RingLocator::Locate(const Point2d& p, double tolerance) const {
  if (NearBoundary(p, tolerance)) return PointLocation::kBoundary;
  return InsideParity(p) ? PointLocation::kInside : PointLocation::kOutside;
}

double RingLocator::BoundaryDistance(const Point2d& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Edge& e : edges_) best = std::min(best, SegmentDistance(p, e.a, e.b));
  return best;
}

}  // namespace acdplan::acd::internal
