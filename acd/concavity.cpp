#include "acd/concavity.h"

#include <CGAL/convex_hull_2.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "acd/internal/exact_predicates.h"
#include "acd/internal/is_notch.h"
#include "acd/internal/pocket_cache.h"
#include "acd/internal/point_tree.h"
#include "acd/internal/rounding_noise.h"
#include "acd/internal/shortest_paths.h"
#include "acd/internal/thread_scratch.h"
#include "base/bit_hash.h"

namespace acdplan::acd {
namespace {

using internal::IsNotchInline;
using internal::Orientation;

// The distance from points to the segment a-b (a bridge), its terms computed once per segment.
class DistanceToSegment {
 public:
  DistanceToSegment(const Point2d& a, const Point2d& b)
      : a_(a), ab_(b - a), length2_(ab_.squaredNorm()) {}
  double operator()(const Point2d& p) const {
    if (length2_ == 0.0) return (p - a_).norm();
    const double t = std::clamp((p - a_).dot(ab_) / length2_, 0.0, 1.0);
    return (p - (a_ + t * ab_)).norm();
  }

 private:
  Point2d a_, ab_;
  double length2_;
};

// A pocket: the ring from hull vertex `begin` forward to hull vertex `end` (the bridge is
// end -> begin across the hull), with at least one vertex in between.
struct Pocket {
  int begin;
  int end;
};

// The pockets of one hull gap, from hull vertex `begin` forward to hull vertex `end` (the
// bridge). Ring vertices lying on the bridge (on the hull boundary) split a pocket, so every
// pocket vertex is strictly inside.
void AppendGapPockets(const Ring2d& ring, int begin, int end, std::vector<Pocket>* pockets) {
  const int n = static_cast<int>(ring.size());
  const int gap = (end - begin + n) % n;
  if (gap <= 1) return;
  int start = begin;
  int since_start = 0;  // (i - start) mod n, without a division per vertex.
  for (int step = 1, i = begin; step < gap; ++step) {
    i = i + 1 == n ? 0 : i + 1;
    ++since_start;
    if (Orientation(ring[begin], ring[end], ring[i]) == 0) {
      if (since_start > 1) pockets->push_back({start, i});
      start = i;
      since_start = 0;
    }
  }
  if ((end - start + n) % n > 1) pockets->push_back({start, end});
}

Ring2d PocketChain(const Ring2d& ring, const Pocket& pocket) {
  const int n = static_cast<int>(ring.size());
  Ring2d chain;
  for (int i = pocket.begin;; i = (i + 1) % n) {
    chain.push_back(ring[i]);
    if (i == pocket.end) break;
  }
  return chain;
}

// Observation A.5: SL may under-measure a pocket only if one of its edges faces away from the
// bridge (a "hazard"): its outward normal has a negative dot product with the bridge's; rotating
// both normals alike, the edge direction is against the bridge direction. Without a hazard the
// chain is monotone along the bridge, every vertex sees the bridge straight on, and SP == SL
// exactly; hence H1 equals SP (Ch. IV.A.1.c observes identical decompositions) and SP skips the
// triangulation for such pockets. H2 runs SP only where SL stays within tau (Algorithm 4).

// The antipodal pair of a hole and the distance between them (Ch. IV.A.2.b). `hole` is
// clockwise; the hole region as a polygon of its own is the reversed, counter-clockwise ring.
using Antipodes = internal::HoleAntipodes;

Antipodes PrincipalAxisAntipodes(const Ring2d& hole) {
  Point2d mean = Point2d::Zero();
  for (const Point2d& p : hole) mean += p;
  mean /= static_cast<double>(hole.size());
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const Point2d& p : hole) covariance += (p - mean) * (p - mean).transpose();
  // Eqn. 4.1: the principal axis is the eigenvector of the largest eigenvalue.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance);
  const Point2d axis = solver.eigenvectors().col(1);
  int lo = 0, hi = 0;
  for (int i = 1; i < static_cast<int>(hole.size()); ++i) {
    if (hole[i].dot(axis) < hole[lo].dot(axis)) lo = i;
    if (hole[i].dot(axis) > hole[hi].dot(axis)) hi = i;
  }
  return {lo, hi, (hole[lo] - hole[hi]).norm()};
}

// Two shortest-path sweeps inside the hole region: from a principal-axis extreme to the
// geodesically farthest vertex, and from there to its farthest. A lower bound of the geodesic
// diameter that, unlike the principal axis, follows a winding hole (Fig. 20).
Antipodes GeodesicAntipodes(const Ring2d& hole) {
  const Ring2d region = Reversed(hole);
  const int n = static_cast<int>(hole.size());
  auto farthest = [&](int source) {
    const internal::ShortestPathTree tree = internal::ComputeShortestPathTree(region, source);
    const int far = static_cast<int>(std::max_element(tree.distance.begin(), tree.distance.end()) -
                                     tree.distance.begin());
    return std::make_pair(far, tree.distance[far]);
  };
  const int start = n - 1 - PrincipalAxisAntipodes(hole).a;
  const int first = farthest(start).first;
  const auto [second, distance] = farthest(first);
  // Back to indices of the clockwise hole ring.
  return {n - 1 - first, n - 1 - second, distance};
}

bool UseGeodesic(const ConcavityOptions& options) {
  switch (options.hole_diameter) {
    case HoleDiameter::kPrincipalAxis:
      return false;
    case HoleDiameter::kGeodesic:
      return true;
    case HoleDiameter::kAuto:
      break;
  }
  return options.measure == ConcavityMeasure::kShortestPath ||
         options.measure == ConcavityMeasure::kHybrid1;
}

// What MeasureHoles() may take over from the parent's searches (nothing for a whole measure):
// the parent's per hole, which of them the piece's holes are, and which outer vertices the
// piece copies (InheritedChain).
class HoleSources {
 public:
  HoleSources() = default;
  HoleSources(const Polygon2d& piece, const internal::InheritedHoles& holes,
              const internal::InheritedChain& chain, int parent_n)
      : chain_(chain), n_(static_cast<int>(piece.outer.size())), parent_n_(parent_n) {
    chain_fits_ = chain.begin >= 0 && chain.length >= 0 && chain.begin + chain.length <= n_ &&
                  chain.length <= parent_n && chain.parent_begin >= 0 &&
                  chain.parent_begin < parent_n;
    if (holes.parent == nullptr || holes.origin == nullptr ||
        holes.origin->size() != piece.holes.size()) {
      return;
    }
    const int parent_k = static_cast<int>(holes.parent->size());
    hole_at_.assign(parent_k, -1);
    int previous = -1;
    for (int i = 0; i < static_cast<int>(holes.origin->size()); ++i) {
      const int j = (*holes.origin)[i];
      // Increasing, so that the piece orders its holes as the parent did (searches break ties
      // by ring).
      if (j <= previous || j >= parent_k) {
        hole_at_.clear();
        return;
      }
      hole_at_[j] = i;
      previous = j;
    }
    holes_ = holes;
  }

  // The parent's searches for hole i of the piece, or nullptr.
  const internal::HoleNeighbours* Parent(int i) const {
    return hole_at_.empty() ? nullptr : &(*holes_.parent)[(*holes_.origin)[i]];
  }
  // Where the piece holds the parent's hole j, or -1.
  int HoleAt(int j) const {
    return j >= 0 && j < static_cast<int>(hole_at_.size()) ? hole_at_[j] : -1;
  }
  // Whether the chain fits the piece's and the parent's outer rings.
  bool ChainFits() const { return chain_fits_; }
  // Whether the piece's outer ring holds vertices the chain does not copy.
  bool HasNewVertices() const { return NewBegin() > 0 || NewEnd() < n_; }
  // Where the piece's outer ring holds the parent's outer vertex j, or -1.
  int CopiedAt(int j) const {
    if (!chain_fits_) return -1;
    const int offset =
        j >= chain_.parent_begin ? j - chain_.parent_begin : j + parent_n_ - chain_.parent_begin;
    return offset < chain_.length ? chain_.begin + offset : -1;
  }
  // The piece's outer vertices the chain does not copy: [0, NewBegin()) and [NewEnd(), n).
  int NewEnd() const { return chain_fits_ ? chain_.begin + chain_.length : 0; }
  int NewBegin() const { return chain_fits_ ? chain_.begin : 0; }

 private:
  internal::InheritedHoles holes_;
  std::vector<int> hole_at_;  // Per parent hole; empty: nothing inherited.
  internal::InheritedChain chain_;
  int n_ = 0, parent_n_ = 0;  // The piece's and the parent's outer vertices.
  bool chain_fits_ = false;
};

// The vertex searches of MeasureHoles(), each tree built when first needed: over the whole
// outer ring, over the outer vertices a piece does not copy from its parent, over all holes.
// Each search returns what a scan of the rings in order (outer first, then hole 0, 1, ...)
// would: the closest vertex of each ring (lowest index on equal squared distance), and of
// those the one at the smallest distance, the first ring on equal distance.
class VertexSearch {
 public:
  VertexSearch(const Polygon2d& polygon, const HoleSources& sources)
      : polygon_(polygon), sources_(sources) {}

  // What a search from antipode `p` of hole `hole` finds, taking over what the parent's
  // search `parent` found where the piece cannot change it (nullptr: nothing to take over).
  internal::AntipodeNeighbours Find(const Point2d& p, int hole,
                                    const internal::AntipodeNeighbours* parent) {
    internal::AntipodeNeighbours found;
    // The parent's outer vertex, if the piece has it and nothing else was as near, unless one
    // of the piece's new vertices is nearer.
    const int copied =
        parent != nullptr && !parent->outer.tie ? sources_.CopiedAt(parent->outer.vertex) : -1;
    if (copied >= 0) {
      found.outer = {copied, parent->outer.d2, false};
      if (sources_.HasNewVertices()) {
        Offer(NewVertices(), sources_.NewBegin(), sources_.NewEnd(), p, &found.outer);
      }
    } else {
      Offer(WholeRing(), 0, 0, p, &found.outer);
    }
    const double d = std::sqrt(found.outer.d2);
    // The parent's hole vertex holds if it was the nearest of all the parent's other holes
    // (it lay within the parent's outer distance) and is on a hole of the piece; if every other
    // hole lay farther than the parent's outer vertex, they lie farther than this one too.
    const double parent_d = parent != nullptr ? std::sqrt(parent->outer.d2) : 0.0;
    const bool parent_nearest = parent != nullptr && parent->hole.distance <= parent_d;
    const int ring = parent_nearest ? sources_.HoleAt(parent->hole.ring) : -1;
    if (ring >= 0) {
      found.hole = parent->hole;
      found.hole.ring = ring;
    } else if (parent != nullptr && !parent_nearest && d <= parent_d) {
      found.hole = {};
    } else {
      found.hole = ClosestOnHoles(p, hole, d);
    }
    return found;
  }

 private:
  // A tree over the outer vertices but [begin, end), whose ids count the others in order.
  static internal::PointTree OuterTree(const Ring2d& ring, int begin, int end) {
    std::vector<Point2d> points;
    points.reserve(ring.size() - (end - begin));
    points.insert(points.end(), ring.begin(), ring.begin() + begin);
    points.insert(points.end(), ring.begin() + end, ring.end());
    return internal::PointTree(std::move(points), {begin});
  }
  const internal::PointTree& WholeRing() {
    if (!whole_ring_) whole_ring_.emplace(OuterTree(polygon_.outer, 0, 0));
    return *whole_ring_;
  }
  const internal::PointTree& NewVertices() {
    if (!new_vertices_) {
      new_vertices_.emplace(OuterTree(polygon_.outer, sources_.NewBegin(), sources_.NewEnd()));
    }
    return *new_vertices_;
  }

  // Offers `nearest` the vertices of `tree` (an OuterTree() without [begin, end)) that may
  // be as near to `p`.
  static void Offer(const internal::PointTree& tree, int begin, int end, const Point2d& p,
                    internal::NearestVertex* nearest) {
    double radius = std::sqrt(nearest->d2);
    tree.Search(p, &radius, [&](int id, double d2) {
      nearest->Offer(id < begin ? id : id + end - begin, d2);
      radius = std::sqrt(nearest->d2);
    });
  }

  // The closest vertex to `p` on a hole other than `skip`, ordered by distance, then ring, then
  // squared distance, then index: the scan's choice among the holes, if it lies within `limit`
  // (any vertex or none otherwise). The limit prunes the search from the start, which matters
  // because the vertices of hole `skip` lie nearest and are all passed over.
  internal::HoleVertex ClosestOnHoles(const Point2d& p, int skip, double limit) {
    if (!holes_) holes_.emplace(HoleTree());
    internal::HoleVertex best;
    double radius = limit;
    holes_->Search(p, &radius, [&](int id, double d2) {
      const int ring = ring_[id];
      if (ring == skip) return;
      const double d = std::sqrt(d2);
      if (d < best.distance ||
          (d == best.distance &&
           (ring < best.ring || (ring == best.ring &&
                                 (d2 < best.d2 || (d2 == best.d2 && index_[id] < best.vertex)))))) {
        best = {ring, index_[id], d2, d};
        radius = std::min(radius, d);
      }
    });
    return best;
  }

  // A tree over the vertices of all holes, runs split at each hole's first vertex.
  internal::PointTree HoleTree() {
    std::vector<Point2d> points;
    std::vector<int> ring_begin;
    size_t count = 0;
    for (const Ring2d& hole : polygon_.holes) count += hole.size();
    points.reserve(count);
    ring_.reserve(count);
    index_.reserve(count);
    for (int k = 0; k < static_cast<int>(polygon_.holes.size()); ++k) {
      ring_begin.push_back(static_cast<int>(points.size()));
      for (int i = 0; i < static_cast<int>(polygon_.holes[k].size()); ++i) {
        points.push_back(polygon_.holes[k][i]);
        ring_.push_back(k);
        index_.push_back(i);
      }
    }
    return internal::PointTree(std::move(points), ring_begin);
  }

  const Polygon2d& polygon_;
  const HoleSources& sources_;
  std::optional<internal::PointTree> whole_ring_, new_vertices_, holes_;
  std::vector<int> ring_, index_;  // Per hole vertex of holes_: its hole and index.
};

// Where a hole meets the rest of the polygon: the vertex x of another ring closest to one of
// the hole's antipodes.
struct HoleLink {
  int ring = -1;   // -1: the outer ring; j >= 0: hole j.
  int vertex = 0;  // x.
  int end = 0;     // 0: p is the antipode closest to x; 1: cw(p) is.
  double distance = std::numeric_limits<double>::infinity();
};

// Hole concavity, Eqn. 4.2: concavity(P_i) = concavity(x) + dist(x, p_i) + dist(p_i, cw(p_i))
// + delta, where x is the vertex closest to p_i not in P_i and concavity(x) is concavity(P_j)
// when x lies on hole P_j (Fig. 23: holes behind holes are deeper). The equation leaves cycles
// open (two holes closest to each other); see the loop below.
std::vector<HoleConcavity> MeasureHoles(const Polygon2d& polygon,
                                        const std::vector<double>& outer_concavity, double delta,
                                        const ConcavityOptions& options, const HoleSources& sources,
                                        std::vector<internal::HoleNeighbours>* found) {
  const int k = static_cast<int>(polygon.holes.size());
  std::vector<HoleConcavity> holes(k);
  found->resize(k);
  if (k == 0) return holes;
  const bool geodesic = UseGeodesic(options);
  std::vector<HoleLink> nearest(k), nearest_outer(k);
  VertexSearch search(polygon, sources);
  for (int i = 0; i < k; ++i) {
    const Ring2d& hole = polygon.holes[i];
    const internal::HoleNeighbours* parent = sources.Parent(i);
    internal::HoleNeighbours& mine = (*found)[i];
    mine.antipodes = parent != nullptr ? parent->antipodes
                     : geodesic        ? GeodesicAntipodes(hole)
                                       : PrincipalAxisAntipodes(hole);
    const Antipodes& pair = mine.antipodes;
    holes[i].p = pair.a;
    holes[i].cw_p = pair.b;
    holes[i].diameter = pair.distance;
    for (int end = 0; end < 2; ++end) {
      const Point2d& a = hole[end == 0 ? pair.a : pair.b];
      const internal::AntipodeNeighbours& near = mine.ends[end] =
          search.Find(a, i, parent != nullptr ? &parent->ends[end] : nullptr);
      const int x = near.outer.vertex;
      const double d = std::sqrt(near.outer.d2);
      // The outer ring comes first: a hole replaces it only when strictly closer.
      const HoleLink link = near.hole.distance < d ? HoleLink{near.hole.ring, near.hole.vertex, end,
                                                              near.hole.distance}
                                                   : HoleLink{-1, x, end, d};
      if (link.distance < nearest[i].distance) nearest[i] = link;
      if (d < nearest_outer[i].distance) nearest_outer[i] = {-1, x, end, d};
    }
  }
  // Settle holes whose x lies on the outer ring or on a settled hole; a cycle of holes closest
  // to each other is broken at the hole cheapest to reach from the outer ring (the first such
  // hole on equal cost). A settled hole settles every hole linked to it, transitively; the
  // holes left are those whose links lead into a cycle, and as settling only ever adds, the
  // cheapest unsettled hole is each time the next unsettled one in order of cost.
  std::vector<bool> settled(k, false);
  auto settle = [&](int i, const HoleLink& link, double at_x) {
    if (link.end == 1) std::swap(holes[i].p, holes[i].cw_p);
    holes[i].depth = at_x + link.distance;
    holes[i].concavity = holes[i].depth + holes[i].diameter + delta;
    settled[i] = true;
  };
  // The holes linked to each hole (CSR).
  std::vector<int> linked_begin(k + 1, 0), linked(k);
  for (int i = 0; i < k; ++i) {
    if (nearest[i].ring >= 0) ++linked_begin[nearest[i].ring + 1];
  }
  for (int j = 0; j < k; ++j) linked_begin[j + 1] += linked_begin[j];
  {
    std::vector<int> fill(linked_begin.begin(), linked_begin.end() - 1);
    for (int i = 0; i < k; ++i) {
      if (nearest[i].ring >= 0) linked[fill[nearest[i].ring]++] = i;
    }
  }
  std::vector<int> stack;
  auto settle_linked = [&](int root) {
    stack.assign(1, root);
    while (!stack.empty()) {
      const int j = stack.back();
      stack.pop_back();
      for (int e = linked_begin[j]; e < linked_begin[j + 1]; ++e) {
        const int i = linked[e];
        if (settled[i]) continue;
        settle(i, nearest[i], holes[j].concavity);
        stack.push_back(i);
      }
    }
  };
  for (int i = 0; i < k; ++i) {
    if (nearest[i].ring >= 0) continue;
    settle(i, nearest[i], outer_concavity[nearest[i].vertex]);
    settle_linked(i);
  }
  std::vector<double> cost(k);
  std::vector<int> by_cost(k);
  for (int i = 0; i < k; ++i) {
    cost[i] = outer_concavity[nearest_outer[i].vertex] + nearest_outer[i].distance;
    by_cost[i] = i;
  }
  std::sort(by_cost.begin(), by_cost.end(),
            [&](int a, int b) { return cost[a] < cost[b] || (cost[a] == cost[b] && a < b); });
  for (const int i : by_cost) {
    if (settled[i]) continue;
    settle(i, nearest_outer[i], outer_concavity[nearest_outer[i].vertex]);
    settle_linked(i);
  }
  return holes;
}

}  // namespace

bool IsNotch(const Point2d& prev, const Point2d& v, const Point2d& next) {
  return internal::IsNotchInline(prev, v, next);
}

int CountNotches(const Polygon2d& polygon) {
  int count = 0;
  auto count_ring = [&count](const Ring2d& ring) {
    if (ring.empty()) return;
    // Walks the ring with its three vertices at hand (no index arithmetic per vertex).
    const Point2d* prev = &ring.back();
    const Point2d* v = &ring.front();
    for (size_t i = 1; i <= ring.size(); ++i) {
      const Point2d* next = &ring[i == ring.size() ? 0 : i];
      count += internal::IsNotchInline(*prev, *v, *next);
      prev = v;
      v = next;
    }
  };
  count_ring(polygon.outer);
  for (const Ring2d& hole : polygon.holes) count_ring(hole);
  return count;
}

namespace {

// Melkman's linear-time hull of a simple polygonal chain: the points ring[index(k)],
// k = 0..count-1, in ring order (increasing indices), started at `start` if it is known to be a
// strict hull vertex, else at the lexicographically smallest point (always one), with exact
// orientation; strict turns only. Puts ring indices in increasing order into `hull` (in the
// storage it holds). `convex_prefix`: how many points from `start` on are known to be
// consecutive strict hull vertices (as the parent's hull vertices a piece inherits); at least 3
// of them start the deque as they are.
template <typename Index>
void MelkmanHull(const Ring2d& ring, int count, Index index, std::vector<int>* hull, int start = -1,
                 int convex_prefix = 0) {
  const int n = count;
  hull->clear();
  if (n < 3) {
    for (int k = 0; k < n; ++k) hull->push_back(index(k));
    return;
  }
  if (start < 0) {
    start = 0;
    for (int k = 1; k < n; ++k) {
      const Point2d& p = ring[index(k)];
      const Point2d& q = ring[index(start)];
      if (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y())) start = k;
    }
  }
  auto at = [&](int k) { return index(start + k < n ? start + k : start + k - n); };
  auto turn = [&](int a, int b, int c) { return Orientation(ring[a], ring[b], ring[c]); };
  // A deque in a flat array: [bottom, top] with room to grow both ways. The thread's buffer
  // from the last hull (acd/internal/thread_scratch.h): this runs for every piece, and its
  // allocation cost more than the rest on small pieces. Not zeroed: every slot is written
  // before it is read.
  thread_local std::vector<int> deque_buffer;
  const internal::ScratchScope deque_scope(deque_buffer);
  if (deque_buffer.size() < static_cast<size_t>(2 * n + 3)) deque_buffer.resize(2 * n + 3);
  int* const deque = deque_buffer.data();
  int bottom = n, top = n - 1;
  auto push_top = [&](int v) { deque[++top] = v; };
  auto push_bottom = [&](int v) { deque[--bottom] = v; };
  int k = 2;
  if (convex_prefix >= 3) {
    // What the loop below would build from them: the last on both ends, the others in order
    // (each is outside the hull of those before it, on no edge's line).
    k = std::min(convex_prefix, n) - 1;
    push_top(at(k));
    for (int j = 0; j <= k; ++j) push_top(at(j));
  } else {
    // Skip vertices collinear with the first edge: they lie on it (the chain is simple).
    int second = at(1);
    while (k < n && turn(at(0), second, at(k)) == 0) second = at(k++);
    if (k == n) {
      *hull = {std::min(at(0), second), std::max(at(0), second)};
      return;
    }
    const int third = at(k);
    push_top(third);
    if (turn(at(0), second, third) > 0) {
      push_top(at(0));
      push_top(second);
    } else {
      push_top(second);
      push_top(at(0));
    }
    push_top(third);
  }
  // The deque's top edge (deque[top - 1] -> deque[top]) and bottom edge (deque[bottom] ->
  // deque[bottom + 1]) with their vectors: most vertices fall inside and leave both alone.
  struct Edge {
    Point2d from, along, to;
    void Set(const Point2d& a, const Point2d& b) {
      from = a;
      to = b;
      along = b - a;
    }
    int Turn(const Point2d& c) const { return internal::OrientationAlong(from, along, to, c); }
  };
  Edge top_edge, bottom_edge;
  top_edge.Set(ring[deque[top - 1]], ring[deque[top]]);
  bottom_edge.Set(ring[deque[bottom]], ring[deque[bottom + 1]]);
  for (++k; k < n; ++k) {
    const int v = at(k);
    const Point2d& point = ring[v];
    // Inside the current hull or on its boundary (then it cannot be a strict hull vertex, and
    // letting it in would pop true hull vertices that are collinear with it).
    const int top_turn = top_edge.Turn(point);
    int bottom_turn = 2;  // Not taken yet.
    if (top_turn >= 0) {
      bottom_turn = bottom_edge.Turn(point);
      if (bottom_turn >= 0) continue;
    }
    // Each loop's first turn is one taken above (the exact sign of a cyclic permutation is
    // the same, and pushing on top leaves the two bottom entries as they were).
    if (top - bottom >= 2 && top_turn <= 0) {
      --top;
      while (top - bottom >= 2 && turn(deque[top - 1], deque[top], v) <= 0) --top;
    }
    push_top(v);
    if (top - bottom >= 2 &&
        (bottom_turn != 2 ? bottom_turn : turn(v, deque[bottom], deque[bottom + 1])) <= 0) {
      ++bottom;
      while (top - bottom >= 2 && turn(v, deque[bottom], deque[bottom + 1]) <= 0) ++bottom;
    }
    push_bottom(v);
    top_edge.Set(ring[deque[top - 1]], point);
    bottom_edge.Set(point, ring[deque[bottom + 1]]);
  }
  // The deque runs counter-clockwise, which for a counter-clockwise ring is the ring order from
  // some vertex on: rotated to start at the least index, unless the ring turns the other way.
  const int* hull_begin = deque + bottom;
  const int* hull_end = deque + top;  // Drops the repeated end.
  const int* least = std::min_element(hull_begin, hull_end);
  hull->insert(hull->end(), least, hull_end);
  hull->insert(hull->end(), hull_begin, least);
  if (!std::is_sorted(hull->begin(), hull->end())) std::sort(hull->begin(), hull->end());
}

// ConvexHullIndices() into `hull`, in the storage it holds.
void RingHull(const Ring2d& ring, std::vector<int>* hull) {
  MelkmanHull(
      ring, static_cast<int>(ring.size()), [](int k) { return k; }, hull);
}

}  // namespace

std::vector<int> ConvexHullIndices(const Ring2d& ring) {
  std::vector<int> hull;
  RingHull(ring, &hull);
  return hull;
}

Ring2d ConvexHull(const Ring2d& points) {
  // Any point set: CGAL's hull (Akl-Toussaint / Graham-Andrew), counter-clockwise.
  std::vector<internal::Kernel::Point_2> in, out;
  in.reserve(points.size());
  for (const Point2d& p : points) in.push_back(internal::ToCgal(p));
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
  Ring2d hull;
  hull.reserve(out.size());
  for (const auto& p : out) hull.emplace_back(p.x(), p.y());
  return hull;
}

Concavity2d MeasureConcavity(const Polygon2d& polygon, const ConcavityOptions& options) {
  return internal::MeasureConcavityCached(polygon, options, nullptr);
}

namespace internal {

std::uint64_t PocketCache::Hash(const Ring2d& chain) {
  std::uint64_t h = kBitHashSeed ^ chain.size();
  for (const Point2d& p : chain) h = BitHash(BitHash(h, p.x()), p.y());
  return h;
}

const std::vector<double>* PocketCache::Find(const Ring2d& chain) const {
  const auto [first, last] = entries_.equal_range(Hash(chain));
  for (auto it = first; it != last; ++it) {
    if (it->second.chain == chain) return &it->second.distances;
  }
  return nullptr;
}

void PocketCache::Insert(const Ring2d& chain, std::vector<double> distances) {
  entries_.emplace(Hash(chain), Entry{chain, std::move(distances)});
}

namespace {

// The concavity of the vertices of `pocket` for the measures beyond SL, given its SL distances
// in result->outer and whether it has a hazard: SL distances are final for SL, for H2 when they
// exceed tau, and for SP and H1 when the pocket has no hazard (see PocketConcavity()). Returns
// the largest final concavity in the pocket (`sl_max` where the SL distances stay).
double FinishPocket(const Ring2d& ring, const Pocket& pocket, bool hazard, double sl_max,
                    const ConcavityOptions& options, PocketCache* cache, Concavity2d* result) {
  const int n = static_cast<int>(ring.size());
  const bool needs_sp =
      hazard && (options.measure == ConcavityMeasure::kShortestPath ||
                 options.measure == ConcavityMeasure::kHybrid1 ||
                 (options.measure == ConcavityMeasure::kHybrid2 && sl_max <= options.tau));
  if (!needs_sp) return sl_max;
  const Ring2d chain = PocketChain(ring, pocket);
  const std::vector<double>* cached = cache != nullptr ? cache->Find(chain) : nullptr;
  std::vector<double> computed;
  if (cached == nullptr) {
    computed = internal::ShortestPathsToBridge(chain);
    if (cache != nullptr) cache->Insert(chain, computed);
  }
  const std::vector<double>& d = cached != nullptr ? *cached : computed;
  double largest = 0.0;
  for (size_t k = 1; k + 1 < chain.size(); ++k) {
    result->outer[(pocket.begin + static_cast<int>(k)) % n] = d[k];
    largest = std::max(largest, d[k]);
  }
  return largest;
}

// The concavity of every vertex strictly between ring vertices `begin` and `end` (Ch. IV.A.1)
// into result->outer; returns the largest. `whole_gap`: the two are consecutive hull vertices,
// whose gap holds several pockets (the bridges and pockets of Ch. III.B, Observation B.3) where
// vertices lie on the bridge: then it is split by AppendGapPockets() and each pocket measured on
// its own. A vertex on the bridge lies between its ends (every vertex lies in the hull), so its
// SL distance is rounding noise, far below `on_bridge`: the exact test runs only for distances
// that small, in the pass that takes the SL distances.
double MeasureSpan(const Ring2d& ring, int begin, int end, bool whole_gap,
                   const ConcavityOptions& options, PocketCache* cache, Concavity2d* result) {
  const int n = static_cast<int>(ring.size());
  const Point2d& from = ring[begin];
  const Point2d& to = ring[end];
  const Point2d bridge = to - from;
  const DistanceToSegment distance(from, to);
  // Distances are never negative: a pocket is never split.
  const double on_bridge = whole_gap ? 1e-9 * (MaxAbs(from) + MaxAbs(to) + MaxAbs(bridge)) : -1.0;
  bool hazard = false;
  double sl_max = 0.0;
  for (int i = begin; i != end;) {
    const int next = i + 1 == n ? 0 : i + 1;
    hazard = hazard || (ring[next] - ring[i]).dot(bridge) < 0.0;
    if (i != begin) {
      const double d = distance(ring[i]);
      if (d <= on_bridge && Orientation(from, to, ring[i]) == 0) {  // Several pockets.
        std::vector<Pocket> pockets;
        AppendGapPockets(ring, begin, end, &pockets);
        double largest = 0.0;  // (A vertex on the bridge, between pockets, has concavity 0.)
        for (const Pocket& pocket : pockets) {
          largest = std::max(largest, MeasureSpan(ring, pocket.begin, pocket.end,
                                                  /*whole_gap=*/false, options, cache, result));
        }
        return largest;
      }
      result->outer[i] = d;
      sl_max = std::max(sl_max, d);
    }
    i = next;
  }
  return FinishPocket(ring, {begin, end}, hazard, sl_max, options, cache, result);
}

// MeasureSpan() of the hull gap from hull vertex `begin` to hull vertex `end`: the largest
// concavity in it (Concavity2d::bridge_max), -infinity if it is empty.
double MeasureGap(const Ring2d& ring, int begin, int end, const ConcavityOptions& options,
                  PocketCache* cache, Concavity2d* result) {
  const int n = static_cast<int>(ring.size());
  if ((end - begin + n) % n <= 1) return -std::numeric_limits<double>::infinity();
  return MeasureSpan(ring, begin, end, /*whole_gap=*/true, options, cache, result);
}

// The witness notch by the outer concavities alone, into result->value and witness_vertex.
void FindWitnessNotch(const Ring2d& ring, Concavity2d* result) {
  const int n = static_cast<int>(ring.size());
  // The maximum over notches only, the first notch in ring order on equal concavity, when the
  // deepest vertices are no notches. Taken by decreasing concavity: a few passes for the
  // largest value left replace a notch test on every vertex that tops the notches before it
  // in ring order (most do, going down into a pocket). After kRounds values, the ring order.
  const std::vector<double>& concavity = result->outer;
  auto is_notch = [&](int i) { return internal::IsNotchAt(ring, i); };
  constexpr int kRounds = 3;
  double below = std::numeric_limits<double>::infinity();  // Values tried so far are >= this.
  bool settled = false;
  for (int round = 0; round < kRounds && !settled; ++round) {
    double top = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      if (concavity[i] < below && concavity[i] > top) top = concavity[i];
    }
    if (top == -std::numeric_limits<double>::infinity()) {  // No vertex is a notch.
      settled = true;
      break;
    }
    for (int i = 0; i < n; ++i) {
      if (concavity[i] == top && is_notch(i)) {
        result->value = top;
        result->witness_vertex = i;
        settled = true;
        break;
      }
    }
    below = top;
  }
  for (int i = 0; i < n && !settled; ++i) {
    if ((result->witness_vertex < 0 || concavity[i] > result->value) && is_notch(i)) {
      result->value = concavity[i];
      result->witness_vertex = i;
    }
  }
}

// The first notch in ring order among the outer vertices of concavity `top`, the largest
// bridge_max, looked for in the gaps that hold it (the hull vertices, the rest, are no notches:
// each is strictly convex); -1 if none is a notch.
int FirstNotchAtTop(const Ring2d& ring, const Concavity2d& result, double top) {
  const int n = static_cast<int>(ring.size());
  const int h = static_cast<int>(result.hull.size());
  auto first_in = [&](int from, int to) {  // Over [from, to).
    for (int i = from; i < to; ++i) {
      if (result.outer[i] == top && internal::IsNotchAt(ring, i)) {
        return i;
      }
    }
    return -1;
  };
  // The last gap wraps past vertex n - 1: its part before hull[0] comes first in ring order.
  const bool wrap_holds_top = result.bridge_max[h - 1] == top;
  int found = wrap_holds_top ? first_in(0, result.hull[0]) : -1;
  for (int k = 0; k + 1 < h && found < 0; ++k) {
    if (result.bridge_max[k] == top) found = first_in(result.hull[k] + 1, result.hull[k + 1]);
  }
  if (found < 0 && wrap_holds_top) found = first_in(result.hull[h - 1] + 1, n);
  return found;
}

// The witness notch and the holes, once result->outer and result->bridge_max are complete.
void FinishMeasure(const Polygon2d& polygon, const ConcavityOptions& options,
                   const HoleSources& sources, Concavity2d* result,
                   std::vector<HoleNeighbours>* neighbours) {
  const Ring2d& ring = polygon.outer;
  // The maximum over notches only (Lemma C.2: the most concave point is a notch), the first
  // notch in ring order on equal concavity. The deepest vertex of a pocket is extreme in the
  // pocket, so almost always a notch: it is looked for at the largest bridge_max first.
  const double top = result->bridge_max.empty()
                         ? -std::numeric_limits<double>::infinity()
                         : *std::max_element(result->bridge_max.begin(), result->bridge_max.end());
  const int at_top = top >= 0.0 ? FirstNotchAtTop(ring, *result, top) : -1;
  if (at_top >= 0) {
    result->value = top;
    result->witness_vertex = at_top;
  } else if (top >= 0.0) {
    FindWitnessNotch(ring, result);
  }
  const double delta = result->value;
  std::vector<HoleNeighbours> unused;
  result->holes = MeasureHoles(polygon, result->outer, delta, options, sources,
                               neighbours != nullptr ? neighbours : &unused);
  for (int i = 0; i < static_cast<int>(result->holes.size()); ++i) {
    if (result->holes[i].concavity >= result->value) {
      result->value = result->holes[i].concavity;
      result->witness_hole = i;
      result->witness_vertex = -1;
    }
  }
}

// An empty measure that holds the storage of `spare` (if any), to be filled without allocating
// as long as the storage suffices: pieces are measured one after another, each needing about
// the storage of the one before.
Concavity2d Recycled(Concavity2d* spare) {
  Concavity2d result;
  if (spare == nullptr) return result;
  result.outer = std::move(spare->outer);
  result.hull = std::move(spare->hull);
  result.bridge_max = std::move(spare->bridge_max);
  result.outer.clear();
  result.hull.clear();
  result.bridge_max.clear();
  return result;
}

// MeasureConcavityCached() into `result`, empty.
void MeasureWhole(const Polygon2d& polygon, const ConcavityOptions& options, PocketCache* cache,
                  const HoleSources& sources, Concavity2d* result,
                  std::vector<HoleNeighbours>* neighbours) {
  const Ring2d& ring = polygon.outer;
  result->outer.assign(ring.size(), 0.0);
  RingHull(ring, &result->hull);
  const int h = static_cast<int>(result->hull.size());
  result->bridge_max.resize(h);
  for (int k = 0; k < h; ++k) {
    result->bridge_max[k] = MeasureGap(ring, result->hull[k], result->hull[k + 1 == h ? 0 : k + 1],
                                       options, cache, result);
  }
  FinishMeasure(polygon, options, sources, result, neighbours);
}

}  // namespace

Concavity2d MeasureConcavityCached(const Polygon2d& polygon, const ConcavityOptions& options,
                                   PocketCache* cache, std::vector<HoleNeighbours>* neighbours) {
  Concavity2d result;
  MeasureWhole(polygon, options, cache, HoleSources(), &result, neighbours);
  return result;
}

Concavity2d MeasureChildConcavity(const Polygon2d& piece, const InheritedChain& chain,
                                  const Ring2d& parent_ring, const Concavity2d& parent,
                                  const ConcavityOptions& options, PocketCache* cache,
                                  Concavity2d* spare, const InheritedHoles& holes,
                                  std::vector<HoleNeighbours>* neighbours) {
  Concavity2d result = Recycled(spare);
  const int parent_n = static_cast<int>(parent.outer.size());
  const HoleSources sources(piece, holes, chain, parent_n);
  auto measure_whole = [&] {
    MeasureWhole(piece, options, cache, sources, &result, neighbours);
    return std::move(result);
  };
  const Ring2d& ring = piece.outer;
  const int n = static_cast<int>(ring.size());
  const int parent_h = static_cast<int>(parent.hull.size());
  if (!sources.ChainFits() || chain.length < 2 ||
      static_cast<int>(parent.bridge_max.size()) != parent_h || parent_h < 3 ||
      static_cast<int>(parent_ring.size()) != parent_n) {
    return measure_whole();
  }
  // What follows rests on the parent's hull vertices on the chain staying strict hull vertices
  // of the piece, with the parent's hull edges between them. The piece's other vertices are
  // holes' (inside the parent's hull) and the cut's ends on edges, which are rounded and may lie
  // just outside it: one rounded out next to a hull vertex with a nearly flat angle turned that
  // vertex into a point on the piece's hull edge (fuzz_decompose2d). A point outside beyond a
  // single hull edge, strictly inside the lines of the two edges beside it, keeps every hull
  // vertex strict (the hull grows by a triangle on that edge); one beyond more edges, or two
  // ends outside, and the piece is measured whole. The test, exact, finds the hull's wedge
  // around its vertex 0 that holds the point by bisection.
  // Where the piece holds the parent's hull vertex k, or -1 (off the chain).
  auto copied_hull = [&](int k) { return sources.CopiedAt(parent.hull[k]); };
  auto on_chain = [&](int k) { return copied_hull(k) >= 0; };
  enum class Side { kInside, kBeyondOneEdge, kElsewhere };  // Of the parent's hull.
  auto against_parent_hull = [&](const Point2d& p) {
    const Point2d& pivot = parent_ring[parent.hull[0]];
    auto at = [&](int k) -> const Point2d& { return parent_ring[parent.hull[k]]; };
    if (Orientation(pivot, at(1), p) < 0 || Orientation(pivot, at(parent_h - 1), p) > 0) {
      return Side::kElsewhere;
    }
    int lo = 1, hi = parent_h - 1;  // orient(pivot, at(lo), p) >= 0 > orient(pivot, at(hi), p).
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (Orientation(pivot, at(mid), p) >= 0 ? lo : hi) = mid;
    }
    const int next = lo + 1, after_next = next + 1 == parent_h ? 0 : next + 1;
    if (Orientation(at(lo), at(next), p) >= 0) return Side::kInside;
    const bool single = Orientation(at(lo - 1), at(lo), p) > 0 &&
                        Orientation(at(next), at(after_next), p) > 0 &&
                        !(on_chain(lo) && on_chain(next));
    return single ? Side::kBeyondOneEdge : Side::kElsewhere;
  };
  const int after = chain.begin + chain.length;
  const Side start = chain.begin == 1 ? against_parent_hull(ring[0]) : Side::kInside;
  const Side end = after < n ? against_parent_hull(ring[after]) : Side::kInside;
  if (start == Side::kElsewhere || end == Side::kElsewhere ||
      (start == Side::kBeyondOneEdge && end == Side::kBeyondOneEdge)) {
    return measure_whole();
  }
  // The parent's hull vertices on the chain, in chain order: parent.hull increases, so they are
  // those from the first at or after parent_begin on, cyclically, while on the chain. Each is a
  // strict hull vertex of the piece too (see above).
  const int first_k = static_cast<int>(
      std::lower_bound(parent.hull.begin(), parent.hull.end(), chain.parent_begin) -
      parent.hull.begin());
  auto hull_k = [&](int t) {  // The parent's hull index of the t-th on the chain.
    const int k = first_k + t;
    return k < parent_h ? k : k - parent_h;
  };
  auto position = [&](int t) { return copied_hull(hull_k(t)); };
  int m = 0;  // How many are on the chain.
  while (m < parent_h && on_chain(hull_k(m))) ++m;
  if (m < 2) return measure_whole();
  // A gap of the parent's hull between two of them is inherited whole and keeps its bridge: its
  // vertices keep their concavity, and none is a vertex of the piece's hull (the chain lies
  // strictly inside the union of the piece and the pocket, whose hull is the piece's). The hull
  // is built over the other vertices, starting at the first parent hull vertex on the chain.
  result.outer.assign(n, 0.0);
  const int first = position(0), last = position(m - 1);
  const int kept_size = m + (n - 1 - last) + first;
  thread_local std::vector<int> kept_buffer;  // Reused, as MelkmanHull()'s deque.
  const ScratchScope kept_scope(kept_buffer);
  if (kept_buffer.size() < static_cast<size_t>(kept_size)) kept_buffer.resize(kept_size);
  int* const kept = kept_buffer.data();
  for (int t = 0; t < m; ++t) kept[t] = position(t);
  {  // The inherited gaps, and the hull vertices between them (0 in both), in one run.
    const int count = last - first + 1;
    const int from = parent.hull[hull_k(0)];
    const int run = std::min(count, parent_n - from);  // Before the parent's ring wraps.
    std::copy_n(parent.outer.begin() + from, run, result.outer.begin() + first);
    std::copy_n(parent.outer.begin(), count - run, result.outer.begin() + first + run);
  }
  std::iota(kept + m, kept + m + (n - 1 - last), last + 1);
  std::iota(kept + m + (n - 1 - last), kept + kept_size, 0);
  MelkmanHull(
      ring, kept_size, [&](int k) { return kept[k]; }, &result.hull, 0, m);
  // The piece's hull edges, the inherited ones (from one parent hull vertex on the chain to the
  // next: m - 1 edges in a row, from the first's place in the sorted hull) with their bridge_max.
  const int h = static_cast<int>(result.hull.size());
  const int offset = static_cast<int>(
      std::lower_bound(result.hull.begin(), result.hull.end(), first) - result.hull.begin());
  result.bridge_max.resize(h);
  for (int k = 0; k < h; ++k) {
    const int t = k - offset;
    if (0 <= t && t + 1 < m) {
      result.bridge_max[k] = parent.bridge_max[hull_k(t)];
    } else {
      result.bridge_max[k] = MeasureGap(ring, result.hull[k], result.hull[k + 1 == h ? 0 : k + 1],
                                        options, cache, &result);
    }
  }
  FinishMeasure(piece, options, sources, &result, neighbours);
  return result;
}

}  // namespace internal
}  // namespace acdplan::acd
