#include "acd/internal/resolve.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>

#include "acd/internal/edge_grid.h"
#include "acd/internal/exact_predicates.h"
#include "acd/internal/is_notch.h"
#include "acd/internal/nearest_boundary.h"
#include "acd/internal/ring_blocks.h"
#include "acd/internal/ring_locator.h"
#include "acd/internal/rounding_noise.h"
#include "acd/internal/thread_scratch.h"

namespace acdplan::acd::internal {
namespace {

// A point of the boundary where a cut ends: a vertex of a ring, or a new point on an edge.
using Endpoint = BoundaryPoint;

// A candidate end point of a cut with its score (higher is better).
struct Candidate {
  Endpoint end;
  double score;
  int rank = 0;  // Ranks before the score: 1 for a diagonal that must win (see ResolveOptions).
};

const Ring2d& RingOf(const Polygon2d& polygon, int ring) {
  return ring < 0 ? polygon.outer : polygon.holes[ring];
}

int Next(int i, int n) { return i + 1 == n ? 0 : i + 1; }
int Prev(int i, int n) { return i == 0 ? n - 1 : i - 1; }

// The vertex of `ring` farthest along `along`: `preferred` unless one lies farther, then the
// first of those farthest.
int FarthestAlong(const Ring2d& ring, const Point2d& along, int preferred = 0) {
  int farthest = preferred;
  for (int i = 0; i < static_cast<int>(ring.size()); ++i) {
    if (ring[i].dot(along) > ring[farthest].dot(along)) farthest = i;
  }
  return farthest;
}

// Whether a segment leaving `e` toward `target` starts strictly into the interior. Every ring
// keeps the interior on its left (outer counter-clockwise, holes clockwise).
bool LeavesInward(const Polygon2d& polygon, const Endpoint& e, const Point2d& target) {
  const Ring2d& ring = RingOf(polygon, e.ring);
  const int n = static_cast<int>(ring.size());
  if (e.on_edge) return Orientation(ring[e.index], ring[Next(e.index, n)], target) > 0;
  const Point2d& u = ring[Prev(e.index, n)];
  const Point2d& v = ring[e.index];
  const Point2d& w = ring[Next(e.index, n)];
  const int left_of_in = Orientation(u, v, target);
  const int left_of_out = Orientation(v, w, target);
  if (Orientation(u, v, w) > 0) return left_of_in > 0 && left_of_out > 0;
  return left_of_in > 0 || left_of_out > 0;
}

bool IsIncident(const Endpoint& e, int ring, int edge, int n) {
  if (e.ring != ring) return false;
  if (e.on_edge) return edge == e.index;
  const bool from_e = edge == e.index, to_e = Next(edge, n) == e.index;
  return from_e | to_e;  // (No short circuit: which one holds varies at random.)
}

// A query's box, for the scans that test it against every edge's or block's box. The four
// comparisons are taken without short circuits: which side a box misses on varies from one to
// the next and defeats branch prediction, whether it misses mostly does not.
struct QueryBox {
  double xmin, xmax, ymin, ymax;
  // The box of the segment a-b grown by `pad`.
  static QueryBox Around(const Point2d& a, const Point2d& b, double pad) {
    return {std::min(a.x(), b.x()) - pad, std::max(a.x(), b.x()) + pad,
            std::min(a.y(), b.y()) - pad, std::max(a.y(), b.y()) + pad};
  }
  bool Misses(const Point2d& lo, const Point2d& hi) const {
    const bool left = hi.x() < xmin;
    const bool right = lo.x() > xmax;
    const bool below = hi.y() < ymin;
    const bool above = lo.y() > ymax;
    return left | right | below | above;
  }
  // The box of the edge u-w.
  bool MissesEdge(const Point2d& u, const Point2d& w) const {
    return Misses(u.cwiseMin(w), u.cwiseMax(w));
  }
};

// The boundary edges a cut is tested against, and the boundary points nearest to a point. Most
// notches are resolved by their first or second candidate, and a hole path makes a few links, so
// the first few queries scan blocks of edges (the outer ring's and the holes', skipping those
// whose box misses the query's; a nearest-point search takes the blocks by distance), which is
// cheaper than building the grid (several passes and allocations); the grid is built once
// queries keep coming (a hole's fallbacks try many pairs). Both report every edge whose box
// meets the padded box of the segment, and offer the same points in the same order, so what
// follows decides alike.
class EdgeQuery {
 public:
  /// `outer_blocks`: of polygon.outer, with the concavities (they serve BestCandidate() too);
  /// `hole_blocks`, `grid`: storage for the holes' blocks and the grid (Resolve keeps them per
  /// thread).
  EdgeQuery(const Polygon2d& polygon, const RingBlocks& outer_blocks, HoleBlocks* hole_blocks,
            EdgeGrid* grid)
      : polygon_(polygon), outer_blocks_(outer_blocks), hole_blocks_(*hole_blocks), grid_(*grid) {
    hole_blocks_.Assign(polygon.holes);
    edges_ = static_cast<double>(VertexCount(polygon));
  }

  // As EdgeGrid::AnyNear(); `visit` is called at least on every edge whose bounding box meets
  // the box of a-b grown by `pad`.
  template <typename Visit>
  bool AnyNear(const Point2d& a, const Point2d& b, double pad, Visit visit) const {
    if (!grid_built_) Charge(1);
    if (grid_built_) return grid_.AnyNear(a, b, pad, visit);
    const QueryBox query = QueryBox::Around(a, b, pad);
    // The edges block by block: a block whose box misses the query's holds none that meets it.
    auto scan = [&](int ring, const Ring2d& points, int from, int to) {
      const int n = static_cast<int>(points.size());
      for (int i = from; i < to; ++i) {
        if (query.MissesEdge(points[i], points[i + 1 == n ? 0 : i + 1])) continue;
        if (visit(EdgeGrid::Edge{ring, i})) return true;
      }
      return false;
    };
    for (int k = 0; k < outer_blocks_.Count(); ++k) {
      if (query.Misses(outer_blocks_[k].min, outer_blocks_[k].max)) continue;
      if (scan(-1, polygon_.outer, outer_blocks_.Begin(k), outer_blocks_.End(k))) return true;
    }
    for (int k = 0; k < hole_blocks_.Count(); ++k) {
      const HoleBlocks::Block& block = hole_blocks_[k];
      if (query.Misses(block.min, block.max)) continue;
      if (scan(block.hole, polygon_.holes[block.hole], block.begin, block.end)) return true;
    }
    return false;
  }

  // NearestAccepted() (acd/internal/nearest_boundary.h) on the polygon.
  template <typename SkipHole, typename Accept>
  std::optional<BoundaryPoint> Nearest(const Point2d& p, SkipHole skip_hole, Accept accept) const {
    if (!grid_built_) Charge(3);
    if (grid_built_) return NearestAccepted(polygon_, grid_, p, skip_hole, accept);
    if (magnitude_ < 0.0) {  // The largest magnitude of a vertex coordinate: the blocks bound them.
      Point2d largest = Point2d::Zero();
      auto bound = [&](const RunBounds& b) {
        largest = largest.cwiseMax(b.min.cwiseAbs()).cwiseMax(b.max.cwiseAbs());
      };
      for (int k = 0; k < outer_blocks_.Count(); ++k) bound(outer_blocks_[k]);
      for (int k = 0; k < hole_blocks_.Count(); ++k) bound(hole_blocks_[k]);
      magnitude_ = largest.maxCoeff();
    }
    return NearestAccepted(polygon_, outer_blocks_, hole_blocks_, magnitude_, p, skip_hole, accept);
  }

  const RingBlocks& OuterBlocks() const { return outer_blocks_; }

 private:
  // Counts what a scan of the blocks costs, `weight` per block (a box test: 1; a nearest-point
  // search, which also orders them: 3), and builds the grid once the scans have cost kGridCost
  // per edge. A build costs 60 - 100 instructions per edge, 8 - 12 box tests; buying at about
  // half that (rent or buy) since queries come in runs: a hole path across many holes makes
  // dozens (the GIS tile of decompose2d_gis_test: ~70 per path; neuron.poly: 7 - 22).
  void Charge(int weight) const {
    spent_ += weight * (outer_blocks_.Count() + hole_blocks_.Count());
    if (spent_ > kGridCost * edges_) BuildGrid();
  }

  void BuildGrid() const {
    grid_.Build(polygon_);
    grid_built_ = true;
  }

  static constexpr double kGridCost = 4;
  const Polygon2d& polygon_;
  const RingBlocks& outer_blocks_;
  HoleBlocks& hole_blocks_;
  EdgeGrid& grid_;
  double edges_;
  mutable double spent_ = 0.0;
  mutable double magnitude_ = -1.0;  // Not known yet.
  mutable bool grid_built_ = false;
};

// |v|, also where its squares underflow: a cut 1e-194 long (a vertex that close to a notch, in
// its cone) is a cut all the same, not one of length 0. Scaled by a power of two there (exact),
// so that elsewhere the result is norm()'s to the bit.
double Length(const Point2d& v) {
  const double squared = v.squaredNorm();
  if (squared >= 1e-280) return std::sqrt(squared);
  constexpr double kScale = 0x1p+600;
  return (v * kScale).norm() / kScale;
}

// Whether the segment a-b is a valid cut: it leaves both ends into the interior and meets no
// boundary edge elsewhere (exact predicates). An end on an edge is a constructed point, the
// rounding of an exact one within kRoundingNoise: exact signs on the rounded point cannot tell
// which side of a vertex the exact cut passes (a cut aimed along a row of collinear vertices
// slips past them by an ulp and leaves a piece pinched to 1e-15, which no later cut resolves).
// Such a cut must therefore also keep every other vertex, and its new end every other edge,
// farther than that noise; and the edge a new end splits must keep every vertex but its own
// ends that far, as the rounded end moves the two edges it leaves by up to the noise (a vertex
// 1e-22 from an edge 5.6e22 long landed on one of them, and the piece pinched there could not
// be resolved). Decided exactly, as a distance computed in floating point errs by the rounding
// of its largest coordinates (an edge 1e26 long makes that 1e10, far above the noise of a cut
// among its small features). Edges are taken from `grid`. `noise_bands` false leaves only the
// exact tests on the rounded points (ResolveOuterNotch()'s last resort checks the pieces instead).
bool IsClearCut(const Polygon2d& polygon, const EdgeQuery& grid, const Endpoint& a,
                const Endpoint& b, bool noise_bands = true) {
  if (!LeavesInward(polygon, a, b.point) || !LeavesInward(polygon, b, a.point)) return false;
  const Kernel::Segment_2 cut(ToCgal(a.point), ToCgal(b.point));
  const bool constructed = noise_bands && (a.on_edge || b.on_edge);
  const double noise =
      constructed ? kRoundingNoise * std::max(MaxAbs(a.point), MaxAbs(b.point)) : 0.0;
  const double noise_squared = noise * noise;
  const double pad = 2.0 * noise;
  const QueryBox query = QueryBox::Around(a.point, b.point, pad);
  // Whether p lies within `noise` of the segment s0-s1: the floating-point distance settles the
  // clear cases (it errs by far less than `screen`), the exact comparison the rest.
  auto near = [&](const Point2d& p, const Point2d& s0, const Point2d& s1, double screen) {
    if (SegmentDistance(p, s0, s1) > screen) return false;
    // Below 1e-154 the square loses its digits: within `screen` counts as near, as it always
    // did (a cut among coordinates that small and none far away, where the screen is tight).
    if (noise_squared < std::numeric_limits<double>::min()) return true;
    return Kernel().compare_squared_distance_2_object()(
               ToCgal(p), Kernel::Segment_2(ToCgal(s0), ToCgal(s1)), noise_squared) != CGAL::LARGER;
  };
  const bool blocked = grid.AnyNear(a.point, b.point, pad, [&](const EdgeGrid::Edge& edge) {
    const Ring2d& ring = RingOf(polygon, edge.ring);
    const int n = static_cast<int>(ring.size());
    const int i = edge.index;
    const Point2d& u = ring[i];
    const Point2d& w = ring[Next(i, n)];
    if (query.MissesEdge(u, w)) return false;
    const bool at_a = IsIncident(a, edge.ring, i, n), at_b = IsIncident(b, edge.ring, i, n);
    if (!at_a && !at_b && CGAL::do_intersect(cut, Kernel::Segment_2(ToCgal(u), ToCgal(w)))) {
      return true;
    }
    if (!constructed) return false;
    const double screen = std::max(noise, kRoundingNoise * std::max(MaxAbs(u), MaxAbs(w)));
    // Vertices of this edge other than the cut's own ends, near the cut.
    for (const Point2d* v : {&u, &w}) {
      if (*v == a.point || *v == b.point) continue;
      if (near(*v, a.point, b.point, screen)) return true;
    }
    // A constructed end near an edge other than its own.
    for (const Endpoint* e : {&a, &b}) {
      if (!e->on_edge || (e->ring == edge.ring && e->index == i)) continue;
      if (IsIncident(*e, edge.ring, i, n)) continue;
      if (near(e->point, u, w, screen)) return true;
    }
    return false;
  });
  if (blocked) return false;
  // The edges the constructed ends split, crowded by a vertex.
  for (const Endpoint* e : {&a, &b}) {
    if (!constructed || !e->on_edge) continue;
    const Ring2d& ring = RingOf(polygon, e->ring);
    const Point2d& u = ring[e->index];
    const Point2d& w = ring[Next(e->index, static_cast<int>(ring.size()))];
    const double screen = std::max(noise, kRoundingNoise * std::max(MaxAbs(u), MaxAbs(w)));
    const bool crowded = grid.AnyNear(u, w, pad, [&](const EdgeGrid::Edge& edge) {
      const Ring2d& other = RingOf(polygon, edge.ring);
      const Point2d& v = other[edge.index];  // Each vertex starts one edge.
      return v != u && v != w && near(v, u, w, std::max(screen, kRoundingNoise * MaxAbs(v)));
    });
    if (crowded) return false;
  }
  return true;
}

bool SegmentsMeet(const Point2d& a, const Point2d& b, const Point2d& c, const Point2d& d) {
  // Boxes apart, segments apart (exact comparisons): most pairs a hole path tests end here.
  if (QueryBox::Around(a, b, 0.0).MissesEdge(c, d)) return false;
  return CGAL::do_intersect(Kernel::Segment_2(ToCgal(a), ToCgal(b)),
                            Kernel::Segment_2(ToCgal(c), ToCgal(d)));
}

// Where the ray v + t d meets the edge from `origin` along `edge` (origin + s edge): t and s,
// or nothing if they are parallel. Accurate near `origin`: the error of s edge is relative to
// the vectors from `origin`, so the edge end nearest to the hit should be `origin`.
struct RayHit {
  double t, s;
};
std::optional<RayHit> RayEdgeHit(const Point2d& v, const Point2d& d, const Point2d& origin,
                                 const Point2d& edge) {
  const double denom = d.x() * edge.y() - d.y() * edge.x();
  if (denom == 0.0) return std::nullopt;
  const Point2d w = origin - v;
  return RayHit{(w.x() * edge.y() - w.y() * edge.x()) / denom,
                (w.x() * d.y() - w.y() * d.x()) / denom};
}

// The first boundary point hit by the ray from vertex `r` of ring `ring` along the bisector of
// the cone its two edges' extensions span (the cut that splits a reflex angle in halves). The
// hit is constructed from the edge end nearer to it, and it snaps to that end only when
// within rounding noise of it (an absolute distance: a bound relative to the edge length
// snapped a hit 1e-7 from the notch on a 6.5e7-long edge to an end 1 unit away, outside the
// cone, and left the notch without a cut).
// Edges are offered one at a time, in ring order (outer ring first, then the holes): on equal
// rounded distances the first edge offered wins, so every search offers them in that order.
class BisectorRay {
 public:
  BisectorRay(const Polygon2d& polygon, int ring_id, int r) : ring_id_(ring_id), r_(r) {
    const Ring2d& ring = RingOf(polygon, ring_id);
    const int n = static_cast<int>(ring.size());
    v_ = ring[r];
    d_ = (v_ - ring[Prev(r, n)]).normalized() + (v_ - ring[Next(r, n)]).normalized();
    valid_ = d_.squaredNorm() >= 1e-24;
    noise_per_l1_ = 1e-9 * (std::abs(d_.x()) + std::abs(d_.y()));
  }

  // Whether the ray has a direction (else it hits nothing).
  bool Valid() const { return valid_; }
  const Point2d& From() const { return v_; }

  // Which side of the ray's line the point v + `to` lies on (the sign), and a bound far above
  // (1e-9 relative) the rounding of that value and of RayEdgeHit()'s for an edge ending there:
  // an edge whose ends lie on one side by more than the sum of their bounds misses the line,
  // and RayEdgeHit() would put the crossing outside it (s < 0 or s > 1).
  double Side(const Point2d& to) const { return d_.x() * to.y() - d_.y() * to.x(); }
  double SideNoise(const Point2d& to) const {
    return noise_per_l1_ * (std::abs(to.x()) + std::abs(to.y()));
  }

  // Offers edge i -> j of ring k (`other`).
  void Offer(int k, const Ring2d& other, int i, int j) {
    if (k == ring_id_ && (i == r_ || j == r_)) return;
    std::optional<RayHit> hit = RayEdgeHit(v_, d_, other[i], other[j] - other[i]);
    if (!hit || hit->t <= 0.0 || hit->s < 0.0 || hit->s > 1.0 || hit->t >= best_t_) return;
    const bool from_end = hit->s > 0.5;
    if (from_end) {  // Again from the nearer end, other[j].
      hit = RayEdgeHit(v_, d_, other[j], other[i] - other[j]);
      if (!hit || hit->t <= 0.0 || hit->t >= best_t_) return;
      hit->s = std::clamp(hit->s, 0.0, 1.0);
    }
    best_t_ = hit->t;
    const int near = from_end ? j : i;
    const Point2d& origin = other[near];
    const Point2d offset = hit->s * (other[from_end ? i : j] - origin);
    const double noise = kRoundingNoise * std::max(1.0, MaxAbs(origin));
    best_ = MaxAbs(offset) <= noise ? Endpoint{k, near, false, origin}
                                    : Endpoint{k, i, true, origin + offset};
    found_ = true;
  }

  // The first hit among the edges offered.
  std::optional<Endpoint> Best() const {
    return found_ ? std::optional<Endpoint>(best_) : std::nullopt;
  }

 private:
  int ring_id_, r_;
  Point2d v_, d_;
  bool valid_;
  double noise_per_l1_;
  double best_t_ = std::numeric_limits<double>::infinity();
  bool found_ = false;
  Endpoint best_;
};

// BisectorRay's first hit over every edge.
// With a finite `reach`, edges whose bounding box keeps farther than `reach` from the vertex (in
// both coordinates) are skipped: a hit returned within `reach` is then still the first hit
// (an edge holding an earlier hit passes the box test), one beyond it may not be.
std::optional<Endpoint> BisectorHit(const Polygon2d& polygon, int ring_id, int r,
                                    double reach = std::numeric_limits<double>::infinity()) {
  BisectorRay ray(polygon, ring_id, r);
  if (!ray.Valid()) return std::nullopt;
  const Point2d& v = ray.From();
  const double xmin = v.x() - reach, xmax = v.x() + reach;
  const double ymin = v.y() - reach, ymax = v.y() + reach;
  // Cohen-Sutherland outcodes: an edge whose two ends share a side of the box misses it.
  auto outcode = [&](const Point2d& p) {
    return (p.x() < xmin ? 1 : 0) | (p.x() > xmax ? 2 : 0) | (p.y() < ymin ? 4 : 0) |
           (p.y() > ymax ? 8 : 0);
  };
  for (int k = -1; k < static_cast<int>(polygon.holes.size()); ++k) {
    const Ring2d& other = RingOf(polygon, k);
    const int m = static_cast<int>(other.size());
    int code_j = m > 0 ? outcode(other[0]) : 0;
    for (int i = 0; i < m; ++i) {
      const int j = Next(i, m);
      const int code_i = code_j;
      code_j = outcode(other[j]);
      if ((code_i & code_j) == 0) ray.Offer(k, other, i, j);
    }
  }
  return ray.Best();
}

double ConcavityAt(const Concavity2d& concavity, const Ring2d& outer, const Endpoint& e) {
  if (!e.on_edge) return concavity.outer[e.index];
  // Interpolated along the edge.
  const int n = static_cast<int>(outer.size());
  const Point2d& a = outer[e.index];
  const Point2d& b = outer[Next(e.index, n)];
  const double s = std::clamp((e.point - a).norm() / std::max((b - a).norm(), 1e-300), 0.0, 1.0);
  return (1.0 - s) * concavity.outer[e.index] + s * concavity.outer[Next(e.index, n)];
}

// Whether a cut from notch v (between a and b) to x resolves v: x lies in the cone where both
// angles at v are at most 180 degrees. A side counts as straight within rounding noise, the
// tolerance IsNotch() uses, so that a rotated copy of a collinear configuration keeps its cuts.
bool InCone(const Point2d& a, const Point2d& v, const Point2d& b, const Point2d& x) {
  return !IsNotchInline(a, v, x) && !IsNotchInline(x, v, b);
}

// Whether a cut from `r` also resolves outer vertex `x`: x is a notch and r lies in its cone.
bool ResolvesBoth(const Ring2d& outer, int x, const Point2d& r) {
  const int n = static_cast<int>(outer.size());
  const Point2d& a = outer[Prev(x, n)];
  const Point2d& b = outer[Next(x, n)];
  return IsNotchInline(a, outer[x], b) && InCone(a, outer[x], b, r);
}

// The score of cut ends for a cut from vertex `index` of ring `ring_id` (Ch. IV.D.1):
// f(r, x) = (1 + s_c concavity(x)) / (s_d dist(r, x)), for the x in the cone that resolves the
// notch (both angles at r at most 180 degrees); times the bonus for a diagonal that also
// resolves x (ResolveOptions::double_resolve_bonus).
class CutScorer {
 public:
  CutScorer(const Polygon2d& polygon, const Concavity2d& concavity, int ring_id, int index,
            const ResolveOptions& options)
      : outer_(polygon.outer),
        concavity_(concavity),
        options_(options),
        ring_id_(ring_id),
        index_(index),
        n_(static_cast<int>(RingOf(polygon, ring_id).size())),
        a_(RingOf(polygon, ring_id)[Prev(index, n_)]),
        r_(RingOf(polygon, ring_id)[index]),
        b_(RingOf(polygon, ring_id)[Next(index, n_)]) {}

  const Point2d& From() const { return r_; }
  const Point2d& Before() const { return a_; }  ///< The vertex before r on its ring.
  const Point2d& After() const { return b_; }   ///< The vertex after r on its ring.

  // Outer vertex i is not a cut end: it is r or one of its neighbours.
  bool Skips(int i) const {
    return ring_id_ < 0 && (i == index_ || i == Prev(index_, n_) || i == Next(index_, n_));
  }

  // Scores `x` into `candidate`; false when x does not resolve r or is r.
  bool Score(const Endpoint& x, Candidate* candidate) const {
    if (!InCone(a_, r_, b_, x.point)) return false;
    const double distance = Length(x.point - r_);
    if (distance == 0.0) return false;
    const double relative_concavity = ConcavityAt(concavity_, outer_, x) / options_.concavity_unit;
    double score = (1.0 + options_.score_concavity * relative_concavity) /
                   (options_.score_distance * distance);
    int rank = 0;
    if (!x.on_edge && concavity_.outer[x.index] > options_.tau &&
        ResolvesBoth(outer_, x.index, r_)) {
      score *= options_.double_resolve_bonus;
      rank = options_.double_resolves_first ? 1 : 0;
    }
    *candidate = {x, score, rank};
    return true;
  }

 private:
  const Ring2d& outer_;
  const Concavity2d& concavity_;
  const ResolveOptions& options_;
  int ring_id_, index_, n_;
  const Point2d &a_, &r_, &b_;
};

// Candidate end points on the outer ring for a cut from vertex `index` of ring `ring_id`,
// scored by CutScorer: every outer vertex, in ring order, then the hit of r's bisector on an
// outer edge.
std::vector<Candidate> ScoredCandidates(const Polygon2d& polygon, const Concavity2d& concavity,
                                        int ring_id, int index, const ResolveOptions& options) {
  const CutScorer scorer(polygon, concavity, ring_id, index, options);
  const Ring2d& outer = polygon.outer;
  std::vector<Candidate> candidates;
  candidates.reserve(outer.size() + 1);
  Candidate candidate;
  const int m = static_cast<int>(outer.size());
  for (int i = 0; i < m; ++i) {
    if (!scorer.Skips(i) && scorer.Score({-1, i, false, outer[i]}, &candidate)) {
      candidates.push_back(candidate);
    }
  }
  // The bisector's hit always resolves the notch and always sees it, so it stays in the list
  // as a last resort even without Steiner cuts: no vertex may lie in the resolving cone.
  if (const std::optional<Endpoint> hit = BisectorHit(polygon, ring_id, index);
      hit && hit->ring < 0 && hit->on_edge && scorer.Score(*hit, &candidate)) {
    if (!options.steiner_cuts) candidate.score = -1.0;
    candidates.push_back(candidate);
  }
  return candidates;
}

// Where a cut end lies along its ring: vertex k at 2k, a point on edge k (after vertex k) at
// 2k + 1.
int RingPosition(const Endpoint& e) { return 2 * e.index + (e.on_edge ? 1 : 0); }

// The candidates' order: by rank, then score; equal ones by their ends' places, the earlier
// along the ring first. A total order, so that the cut taken does not depend on how the
// standard library's heap or sort orders ties (libc++ and libstdc++ differ there).
bool Worse(const Candidate& x, const Candidate& y) {
  if (x.rank != y.rank) return x.rank < y.rank;
  if (x.score != y.score) return x.score < y.score;
  return std::make_pair(x.end.ring, RingPosition(x.end)) >
         std::make_pair(y.end.ring, RingPosition(y.end));
}

// Whether IsNotch(p, v, q) holds clearly: the turn is clockwise by more than twice
// IsNotchInline()'s noise band, counting the rounding of this cheaper form (no exact
// predicate, no square root), so that IsNotchInline() agrees whenever this says yes.
bool ClearlyNotch(const Point2d& p, const Point2d& v, const Point2d& q) {
  const Point2d in = v - p, out = q - v;
  const double left = in.x() * out.y(), right = in.y() * out.x();
  const double turn = right - left;  // > 0: clockwise.
  if (!(turn > 0.0)) return false;
  const double magnitude = std::max({MaxAbs(p), MaxAbs(v), MaxAbs(q), 1.0});
  const double chord_l1 = std::abs(q.x() - p.x()) + std::abs(q.y() - p.y());  // >= |chord|.
  return turn - 1e-15 * (std::abs(left) + std::abs(right)) >
         2.0 * kRoundingNoise * magnitude * chord_l1;
}

// Whether x is clearly outside the cone that resolves notch v between a and b: !InCone().
bool SurelyOutsideCone(const Point2d& a, const Point2d& v, const Point2d& b, const Point2d& x) {
  return ClearlyNotch(a, v, x) || ClearlyNotch(x, v, b);
}

// The best of ScoredCandidates() by Worse(), without listing them. A vertex x scores at most (1 +
// s_c concavity(x) / unit) * bonus / (s_d dist(r, x)) (the bonus only if concavity(x) > tau), so
// once some candidate scores f, every vertex whose bound is below f is skipped on its distance
// alone, and every block of `blocks` (the outer ring's, with the concavities) whose top and box
// bound its vertices so; a point on an edge is bounded with the largest concavity. That first
// candidate is a guess from the blocks nearest to r: the vertex of best score there by a plain
// floating-point cone test, then scored exactly. Which candidate it is changes what is skipped,
// never the result: the best and its ties are visited.
std::optional<Candidate> BestCandidate(const Polygon2d& polygon, const Concavity2d& concavity,
                                       const RingBlocks& blocks, int ring_id, int index,
                                       const ResolveOptions& options) {
  const CutScorer scorer(polygon, concavity, ring_id, index, options);
  const Ring2d& outer = polygon.outer;
  const int m = static_cast<int>(outer.size());
  const Point2d& r = scorer.From();
  auto cross = [](const Point2d& u, const Point2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  // 1 + s_c concavity / unit, to within rounding (the bounds below have slack for it).
  const double per_unit = options.score_concavity / options.concavity_unit;
  auto relative = [&](double c) { return 1.0 + per_unit * c; };
  double max_concavity = 0.0;  // Over all vertices, for the bound on points on edges below.
  for (int b = 0; b < blocks.Count(); ++b) max_concavity = std::max(max_concavity, blocks[b].top);
  // The bisector's first hit over the outer edges, in ring order. Without a diagonal that must
  // win, the bisector's hit is always wanted, and taken here (the first hit is the same; see
  // BisectorHit()). Most edges do not cross the ray's line; they are told by the sides of their
  // ends, and whole blocks by the sides of their boxes' corners.
  const bool ray_here = !options.double_resolves_first;
  BisectorRay ray(polygon, ring_id, index);
  if (ray_here && ray.Valid() && m > 0) {
    // One margin for every edge, at least the sum of its ends' SideNoise(): the noise grows
    // with |to.x| + |to.y|, whose rounded terms are largest, each, at vertices of the hull (the
    // roundings are monotone), so one bound from the hull serves every vertex. An edge within
    // it of the line is offered, to be told by Offer() as before.
    double margin = std::numeric_limits<double>::infinity();
    if (!concavity.hull.empty()) {
      Point2d largest = Point2d::Zero();
      for (const int i : concavity.hull) largest = largest.cwiseMax((outer[i] - r).cwiseAbs());
      margin = 2.0 * ray.SideNoise(largest);
    }
    // A block's corners lie in the hull's box, so their sides and its vertices' err by far less
    // than a millionth of the margin: beyond 1.001 margins at every corner, every vertex of the
    // block is beyond one margin on that side.
    const double block_margin = 1.001 * margin;
    for (int b = 0; b < blocks.Count(); ++b) {
      const RingBlocks::Block& box = blocks[b];
      const double c0 = ray.Side(box.min - r), c1 = ray.Side(box.max - r);
      const double c2 = ray.Side(Point2d(box.min.x(), box.max.y()) - r);
      const double c3 = ray.Side(Point2d(box.max.x(), box.min.y()) - r);
      // All four beyond the margin on one side, without branches (a min and max of the four
      // took several, and whether a block lies across the line comes at random).
      const double above = block_margin, below = -block_margin;
      if (((c0 > above) & (c1 > above) & (c2 > above) & (c3 > above)) |
          ((c0 < below) & (c1 < below) & (c2 < below) & (c3 < below))) {
        continue;
      }
      double side_i = ray.Side(outer[blocks.Begin(b)] - r);
      for (int i = blocks.Begin(b); i < blocks.End(b); ++i) {
        const int j = Next(i, m);
        const double side_j = ray.Side(outer[j] - r);
        // (Without short circuits: the sides alternate unpredictably along the ring.)
        if (((side_i <= margin) | (side_j <= margin)) &
            ((side_i >= -margin) | (side_j >= -margin))) {
          ray.Offer(-1, outer, i, j);
        }
        side_i = side_j;
      }
    }
    for (int k = 0; k < static_cast<int>(polygon.holes.size()); ++k) {
      const Ring2d& hole = polygon.holes[k];
      const int h = static_cast<int>(hole.size());
      for (int i = 0; i < h; ++i) ray.Offer(k, hole, i, Next(i, h));
    }
  }
  // The blocks by distance from r; the guess from the kGuessBlocks nearest. (The thread's
  // buffer from the last call: this runs for every cut.)
  thread_local std::vector<std::pair<double, int>> by_distance;
  const ScratchScope by_distance_scope(by_distance);
  by_distance.resize(blocks.Count());
  for (int b = 0; b < blocks.Count(); ++b) by_distance[b] = {blocks.SquaredDistance(b, r), b};
  std::sort(by_distance.begin(), by_distance.end());
  constexpr int kGuessBlocks = 3;
  const Point2d in = r - scorer.Before(), out = scorer.After() - r;
  int guess = -1;
  double guess_value = 0.0;  // (s_d score)^2 without the bonus.
  for (int k = 0; k < std::min(kGuessBlocks, blocks.Count()); ++k) {
    const int b = by_distance[k].second;
    for (int i = blocks.Begin(b); i < blocks.End(b); ++i) {
      const Point2d to = outer[i] - r;
      const bool before_in = cross(in, to) < 0.0, after_out = cross(out, to) < 0.0;
      if ((before_in | after_out) || scorer.Skips(i)) continue;
      const double d2 = to.squaredNorm();
      const double f = relative(concavity.outer[i]);
      if (d2 > 0.0 && f * f > guess_value * d2) {
        guess = i;
        guess_value = f * f / d2;
      }
    }
  }
  // Every candidate that may reach the floor, the best candidate known so far.
  constexpr double kSlack = 1.0 + 1e-9;  // Against rounding in the bounds.
  const double bonus = std::max(1.0, options.double_resolve_bonus);
  // relative(c), times the bonus above tau: picked from a table, as a branch on c > tau would
  // be taken at random along the ring.
  const double factor[2] = {1.0, bonus};
  auto bound = [&](double c) { return relative(c) * factor[c > options.tau] * kSlack; };
  const double edge_bound = relative(max_concavity) * bonus * kSlack / options.score_distance;
  Candidate floor;
  floor.score = -std::numeric_limits<double>::infinity();
  floor.rank = -1;
  double floor2 = 0.0;                                     // (s_d floor score)^2.
  double reach = std::numeric_limits<double>::infinity();  // No point on an edge wins beyond.
  auto raise_floor = [&](const Candidate& c) {
    floor = c;
    if (c.score > 0.0) {
      floor2 = c.score * options.score_distance * c.score * options.score_distance;
      // Overflowed (the cut is shorter than about 1e-154): its tests would prune the floor's
      // own candidate; with 0 they prune nothing.
      if (!std::isfinite(floor2)) floor2 = 0.0;
      reach = edge_bound / c.score;
    }
  };
  Candidate candidate;
  if (guess >= 0 && scorer.Score({-1, guess, false, outer[guess]}, &candidate)) {
    raise_floor(candidate);
  }
  std::optional<Candidate> result;
  Candidate& best = result.emplace();
  best.score = -std::numeric_limits<double>::infinity();
  best.rank = -1;  // Below every candidate's: still -1 when none was found.
  auto consider = [&](const Candidate& c) {
    if (Worse(best, c)) {
      best = c;
      if (Worse(floor, c)) raise_floor(c);
    }
  };
  auto visit = [&](int i) {
    // Whether x may rank 1 (a diagonal that must win, ResolveOptions::double_resolves_first).
    const double c = concavity.outer[i];
    const bool may_rank = options.double_resolves_first && c > options.tau;
    if (floor.rank == 1 && !may_rank) return;
    if (floor.rank == 1 || !may_rank) {  // Only its score can lift it above the floor.
      const double d2 = (outer[i] - r).squaredNorm();
      const double f = bound(c);
      if (f * f < floor2 * d2) return;
    }
    if (SurelyOutsideCone(scorer.Before(), r, scorer.After(), outer[i])) return;
    if (!scorer.Skips(i) && scorer.Score({-1, i, false, outer[i]}, &candidate)) {
      consider(candidate);
    }
  };
  if (!options.double_resolves_first) {
    // No candidate ranks 1: a block whose bound^2 / dist^2 is below floor2 (1 - 1e-12) is
    // skipped, as the test in visit() would skip each of its vertices (the division rounds by
    // half an ulp; a block's bound is at least each of its vertices', as rounding is monotone).
    // Nearest blocks first, so that the floor rises early; once the largest concavity's bound
    // fails at a block's distance, it fails for every block after it. Vertices are left to
    // visit()'s test, which multiplies where a test here would divide.
    const double top_bound = bound(max_concavity);
    for (const auto& [distance2, b] : by_distance) {
      const double threshold = floor2 * (1.0 - 1e-12);
      if (top_bound * top_bound / distance2 < threshold) break;
      const double block_bound = bound(blocks[b].top);
      if (block_bound * block_bound / distance2 < threshold) continue;
      for (int i = blocks.Begin(b); i < blocks.End(b); ++i) visit(i);
    }
  } else {
    for (int i = 0; i < m; ++i) visit(i);
  }
  // The bisector's hit (see ScoredCandidates()), a point on an edge: rank 0.
  if (floor.rank < 1) {
    const std::optional<Endpoint> hit =
        ray_here ? ray.Best() : BisectorHit(polygon, ring_id, index, reach * 1.000001);
    if (hit && hit->ring < 0 && hit->on_edge && Length(hit->point - r) <= reach &&
        scorer.Score(*hit, &candidate)) {
      if (!options.steiner_cuts) candidate.score = -1.0;
      consider(candidate);
    }
  }
  if (best.rank < 0) result.reset();
  return result;
}

// Calls `accept` on the candidates from best to worst (Worse()) until it returns true; returns
// the accepted candidate. A heap, since the first few candidates usually suffice.
// `best_refused`: the best candidate was already refused.
template <typename Accept>
std::optional<Endpoint> FirstAccepted(std::vector<Candidate> candidates, Accept accept,
                                      bool best_refused = false) {
  if (candidates.empty()) return std::nullopt;
  // Usually the best candidate is accepted: try it before building the heap.
  if (!best_refused) {
    const auto best = std::max_element(candidates.begin(), candidates.end(), Worse);
    if (accept(best->end)) return best->end;
  }
  std::make_heap(candidates.begin(), candidates.end(), Worse);
  std::pop_heap(candidates.begin(), candidates.end(), Worse);  // The best, refused.
  for (auto end = candidates.end() - 1; end != candidates.begin(); --end) {
    std::pop_heap(candidates.begin(), end, Worse);
    if (accept((end - 1)->end)) return (end - 1)->end;
  }
  return std::nullopt;
}

// FirstAccepted(ScoredCandidates(...), accept), listing the candidates only when the best one
// (BestCandidate()) is refused.
template <typename Accept>
std::optional<Endpoint> FirstAcceptedCut(const Polygon2d& polygon, const EdgeQuery& grid,
                                         const Concavity2d& concavity, int ring_id, int index,
                                         const ResolveOptions& options, Accept accept) {
  const std::optional<Candidate> best =
      BestCandidate(polygon, concavity, grid.OuterBlocks(), ring_id, index, options);
  if (!best) return std::nullopt;
  if (accept(best->end)) return best->end;
  return FirstAccepted(ScoredCandidates(polygon, concavity, ring_id, index, options), accept,
                       /*best_refused=*/true);
}

// Outer vertices and (with `edge_points`) closest edge points, nearest first: the fallback
// ends of a hole's cut, and of an outer notch's last resort.
std::vector<Candidate> NearestCandidates(const Polygon2d& polygon, const Point2d& from,
                                         bool edge_points = true) {
  std::vector<Candidate> candidates;
  const Ring2d& outer = polygon.outer;
  const int m = static_cast<int>(outer.size());
  for (int i = 0; i < m; ++i) {
    candidates.push_back({{-1, i, false, outer[i]}, -(outer[i] - from).norm()});
    if (!edge_points) continue;
    if (const std::optional<Point2d> foot = EdgeFoot(from, outer[i], outer[Next(i, m)])) {
      candidates.push_back({{-1, i, true, *foot}, -(*foot - from).norm()});
    }
  }
  return candidates;
}

// How many vertices hole `h` of `polygon` has from index `from` forward to index `to`, both
// included.
int HoleArcSize(const Polygon2d& polygon, int h, int from, int to) {
  const int n = static_cast<int>(polygon.holes[h].size());
  return (to - from + n) % n + 1;
}

// Appends hole `h` of `polygon` from index `from` forward to index `to`, both included, to
// `ring` (with room for them: see AppendOuterChain()); the edge from there on lies on cut
// `cut_after`.
void AppendHoleChain(const Polygon2d& polygon, int h, int from, int to, int cut_after, Ring2d* ring,
                     PieceEdges* edges) {
  const Ring2d& hole = polygon.holes[h];
  const int n = static_cast<int>(hole.size());
  for (int i = from;; i = Next(i, n)) {
    ring->push_back(hole[i]);
    if (i == to) break;
  }
  edges->cuts.push_back({static_cast<int>(ring->size()) - 1, cut_after});
}

// Appends the outer ring from cut end `a` forward to cut end `b`, both included, to `ring`,
// an empty ring, with room for `hole_arcs` more vertices (the arcs of holes the piece runs over
// next: a ring grown for each would be copied each time); the edge from there on lies on cut
// `cut_after`. Sets `chain` to the outer vertices it copies and `edges` to where the edges lie.
// Ends are ordered along the ring by position: vertex k at 2k, a point on edge k at 2k + 1 (two
// ends on one edge never occur: such a cut would run along the edge).
void AppendOuterChain(const Ring2d& outer, const Endpoint& a, const Endpoint& b, int cut_after,
                      int hole_arcs, Ring2d* ring, InheritedChain* chain, PieceEdges* edges) {
  const int n = static_cast<int>(outer.size());
  const int pos_a = RingPosition(a);
  const int pos_b = RingPosition(b);
  const int span = (pos_b - pos_a + 2 * n) % (2 * n);
  const int between = (span - 1 + (pos_a & 1)) / 2;  // Vertices strictly between a and b.
  ring->reserve(ring->size() + between + 2 + hole_arcs);
  ring->push_back(a.on_edge ? a.point : outer[a.index]);
  // The vertices between, in at most two runs of the outer ring.
  const int first = Next(a.index, n);
  const int run = std::min(between, n - first);
  ring->insert(ring->end(), outer.begin() + first, outer.begin() + first + run);
  ring->insert(ring->end(), outer.begin(), outer.begin() + (between - run));
  ring->push_back(b.on_edge ? b.point : outer[b.index]);
  // Edge t from a lies on outer edge a.index + t (the first only in part if a is on it).
  edges->first_outer_edge = a.index;
  edges->outer_count = between + 1;
  edges->cuts.assign(1, {between + 1, cut_after});
  chain->begin = a.on_edge ? 1 : 0;
  chain->parent_begin = a.on_edge ? first : a.index;
  chain->length = between + (a.on_edge ? 0 : 1) + (b.on_edge ? 0 : 1);
}

// Gives each hole of `polygon` not in `skip` to the piece that contains it: the hole's
// first vertex lies strictly inside one piece's ring, as a valid cut keeps clear of other
// holes, so it is located in the smaller ring only (a hole split often cuts off a small piece).
// A piece carries few holes, so one pass over that ring's edges locates them all (the points
// sorted by y; an edge visits those in its y-range): indexing the ring first (a RingLocator)
// cost more than the queries it saved. Exact even-odd parity (RayCrossesEdge()); a point within
// rounding noise of the ring (never the case for a valid cut) is decided by CGAL's exact
// bounded_side_2 instead.
void DistributeHoles(const Polygon2d& polygon, const std::vector<int>& skip,
                     Resolution* resolution) {
  if (polygon.holes.size() <= skip.size()) return;
  std::array<Polygon2d, 2>& pieces = resolution->pieces;
  const int tested = pieces[0].outer.size() <= pieces[1].outer.size() ? 0 : 1;
  const Ring2d& ring = pieces[tested].outer;
  double scale = 0.0;
  for (const Point2d& p : ring) scale = std::max(scale, MaxAbs(p));
  const double noise = kRoundingNoise * std::max(1.0, scale);
  struct Query {  // A hole's first vertex, and what the pass found about it.
    Point2d point;
    int hole;
    bool near = false, inside = false;
  };
  std::vector<Query> queries;
  queries.reserve(polygon.holes.size() - skip.size());
  for (int k = 0; k < static_cast<int>(polygon.holes.size()); ++k) {
    if (std::find(skip.begin(), skip.end(), k) == skip.end()) {
      queries.push_back({polygon.holes[k].front(), k});
    }
  }
  // By y, for the edges' range searches; the order among equal y changes nothing.
  std::sort(queries.begin(), queries.end(),
            [](const Query& a, const Query& b) { return a.point.y() < b.point.y(); });
  const int n = static_cast<int>(ring.size());
  for (int i = 0; i < n; ++i) {
    const Point2d& a = ring[i];
    const Point2d& b = ring[i + 1 == n ? 0 : i + 1];
    const double ylo = std::min(a.y(), b.y()) - noise, yhi = std::max(a.y(), b.y()) + noise;
    const double xlo = std::min(a.x(), b.x()) - noise, xhi = std::max(a.x(), b.x()) + noise;
    auto q = std::lower_bound(queries.begin(), queries.end(), ylo,
                              [](const Query& x, double y) { return x.point.y() < y; });
    for (; q != queries.end() && q->point.y() <= yhi; ++q) {
      const Point2d& p = q->point;
      if (!q->near && xlo <= p.x() && p.x() <= xhi && SegmentDistance(p, a, b) <= noise) {
        q->near = true;
      }
      if (RayCrossesEdge(p, a, b)) q->inside = !q->inside;
    }
  }
  std::sort(queries.begin(), queries.end(),
            [](const Query& a, const Query& b) { return a.hole < b.hole; });
  std::vector<Kernel::Point_2> boundary;
  for (const Query& q : queries) {
    bool inside = q.inside;
    if (q.near) {
      if (boundary.empty()) {
        boundary.reserve(ring.size());
        for (const Point2d& p : ring) boundary.push_back(ToCgal(p));
      }
      inside = CGAL::bounded_side_2(boundary.begin(), boundary.end(), ToCgal(q.point), Kernel()) ==
               CGAL::ON_BOUNDED_SIDE;
    }
    const int side = inside ? tested : 1 - tested;
    pieces[side].holes.push_back(polygon.holes[q.hole]);
    resolution->hole_origins[side].push_back(q.hole);
  }
}

// Empties resolution->pieces, keeping their outer rings' storage (Decompose2d() hands in that
// of pieces split before).
void ClearPieces(Resolution* resolution) {
  for (int side = 0; side < 2; ++side) {
    resolution->pieces[side].outer.clear();
    resolution->pieces[side].holes.clear();
    resolution->hole_origins[side].clear();
    resolution->edges[side].cuts.clear();
  }
}

// Splits `polygon` along the cut from -> to into resolution->pieces.
void SplitAlong(const Polygon2d& polygon, const Endpoint& from, const Endpoint& to,
                Resolution* resolution) {
  ClearPieces(resolution);
  for (int side = 0; side < 2; ++side) {
    AppendOuterChain(polygon.outer, side == 0 ? from : to, side == 0 ? to : from, 0,
                     /*hole_arcs=*/0, &resolution->pieces[side].outer, &resolution->inherited[side],
                     &resolution->edges[side]);
  }
  DistributeHoles(polygon, {}, resolution);
}

// Whether both pieces' outer rings are simple, exactly.
bool PiecesAreSimple(const Resolution& resolution) {
  std::vector<Kernel::Point_2> ring;
  for (const Polygon2d& piece : resolution.pieces) {
    ring.clear();
    for (const Point2d& p : piece.outer) ring.push_back(ToCgal(p));
    if (ring.size() < 3 || !CGAL::is_simple_2(ring.begin(), ring.end(), Kernel())) return false;
  }
  return true;
}

// The cut of outer notch r. `last_resort`: for a notch that every cut misses when cut ends
// must keep clear of other features by their rounding noise (a notch at (999, 4), 7e-15 below
// an edge, where that noise is 1e-10): the first cut that crosses nothing,
// exactly, and leaves two simple pieces, checked exactly on the rounded points; failing that
// (no edge point in the notch's cone is a double apart from it), such a diagonal to the
// nearest vertex, resolving or not. A notch always sees some vertex, and a diagonal leaves two
// pieces of fewer vertices, so the decomposition still ends.
bool ResolveOuterNotch(const Polygon2d& polygon, const EdgeQuery& grid,
                       const Concavity2d& concavity, int r, const ResolveOptions& options,
                       Resolution* resolution, bool last_resort = false) {
  const Endpoint from{-1, r, false, polygon.outer[r]};
  auto accept = [&](const Endpoint& x) {
    if (!last_resort) return IsClearCut(polygon, grid, from, x);
    if (x.point == from.point || !IsClearCut(polygon, grid, from, x, /*noise_bands=*/false)) {
      return false;
    }
    SplitAlong(polygon, from, x, resolution);
    return PiecesAreSimple(*resolution);
  };
  std::optional<Endpoint> to = FirstAcceptedCut(polygon, grid, concavity, -1, r, options, accept);
  if (!to && last_resort) {
    to = FirstAccepted(NearestCandidates(polygon, from.point, /*edge_points=*/false), accept);
  }
  if (!to) return false;
  if (!last_resort) SplitAlong(polygon, from, *to, resolution);  // accept() split the last resort
  resolution->cuts = {{from.point, to->point}};
  resolution->witness = from.point;
  return true;
}

// The first cut of a hole: from hole vertex `a` to the closest visible outer point in its
// cone (Algorithm 5), a diagonal that also resolves an outer notch counting double; else the
// closest visible outer point. The concavity at the far end does not weigh in: this cut only
// joins the hole to the boundary, and a short one leaves the shallowest pocket for the second
// cut (neuron.poly at tau-rel 0.01: SL and H2 164 -> 161 pieces, no acd_bench row rises).
std::optional<Endpoint> FirstHoleCut(const Polygon2d& polygon, const EdgeQuery& grid,
                                     const Concavity2d& concavity, int h, int a,
                                     const ResolveOptions& options) {
  const Endpoint from{h, a, false, polygon.holes[h][a]};
  auto clear = [&](const Endpoint& e) { return IsClearCut(polygon, grid, from, e); };
  ResolveOptions closest = options;
  closest.score_concavity = 0.0;
  std::optional<Endpoint> x = FirstAcceptedCut(polygon, grid, concavity, h, a, closest, clear);
  if (!x) x = FirstAccepted(NearestCandidates(polygon, from.point), clear);
  return x;
}

// The second cut of a hole: from hole vertex `b` to an outer point, crossing neither the first
// cut (a -> x) nor anything else. `thorough` also tries the scored candidates.
std::optional<Endpoint> SecondHoleCut(const Polygon2d& polygon, const EdgeQuery& grid,
                                      const Concavity2d& concavity, int h, int a, const Endpoint& x,
                                      int b, bool thorough, const ResolveOptions& options) {
  const Ring2d& hole = polygon.holes[h];
  const Endpoint from{h, b, false, hole[b]};
  auto compatible = [&](const Endpoint& y) {
    if (y.index == x.index && (y.on_edge == x.on_edge || (y.on_edge && x.on_edge))) return false;
    return !SegmentsMeet(hole[a], x.point, from.point, y.point) &&
           IsClearCut(polygon, grid, from, y);
  };
  std::optional<Endpoint> y;
  if (thorough) y = FirstAcceptedCut(polygon, grid, concavity, h, b, options, compatible);
  if (y) return y;
  std::vector<Candidate> nearest = NearestCandidates(polygon, from.point);
  if (!thorough && nearest.size() > 8) {
    // A quick look at the eight nearest: this is a fallback over many hole vertices.
    std::partial_sort(nearest.begin(), nearest.begin() + 8, nearest.end(),
                      [](const Candidate& u, const Candidate& v) { return Worse(v, u); });
    nearest.resize(8);
  }
  return FirstAccepted(std::move(nearest), compatible);
}

// Splits `polygon` through hole `h` with two cuts, a -> x and b -> y, into two pieces.
void SplitThroughHole(const Polygon2d& polygon, int h, int a, const Endpoint& x, int b,
                      const Endpoint& y, Resolution* resolution) {
  const Ring2d& hole = polygon.holes[h];
  ClearPieces(resolution);
  // Piece 0: outer x..y, cut 1 to b, hole b..a (forward keeps the interior on the left), cut 0
  // to x; piece 1 the other way round.
  Polygon2d* const pieces = resolution->pieces.data();
  PieceEdges* const edges = resolution->edges.data();
  AppendOuterChain(polygon.outer, x, y, 1, HoleArcSize(polygon, h, b, a), &pieces[0].outer,
                   &resolution->inherited[0], &edges[0]);
  AppendHoleChain(polygon, h, b, a, 0, &pieces[0].outer, &edges[0]);
  AppendOuterChain(polygon.outer, y, x, 0, HoleArcSize(polygon, h, a, b), &pieces[1].outer,
                   &resolution->inherited[1], &edges[1]);
  AppendHoleChain(polygon, h, a, b, 1, &pieces[1].outer, &edges[1]);
  DistributeHoles(polygon, {h}, resolution);
  resolution->cuts = {{hole[a], x.point}, {hole[b], y.point}};
  resolution->witness = hole[a];
}

// A path of cuts from the outer boundary through holes back to it: from outer end x, per hole
// crossed the vertex `enter` it arrives at and the vertex `leave` it departs from, to outer
// end y. Consecutive points are joined by cuts.
struct HoleCrossing {
  int hole;
  int enter, leave;
};
struct HolePath {
  Endpoint x, y;
  std::vector<HoleCrossing> holes;  // From the x side to the y side.
};

// Splits `polygon` along `path` into two pieces (the path's cuts cross nothing and each other
// nowhere). Piece 0 runs along the outer ring from x to y and back over the holes' arcs from
// leave to enter; piece 1 from y to x and over the arcs from enter to leave (forward along a
// hole keeps the interior on the left, so each piece stays on one side of every cut).
void SplitAlongPath(const Polygon2d& polygon, const HolePath& path, const Point2d& witness,
                    Resolution* resolution) {
  ClearPieces(resolution);
  // Cut i ends at the i-th hole crossed (cut m, the last, at y).
  const int m = static_cast<int>(path.holes.size());
  Polygon2d* const pieces = resolution->pieces.data();
  PieceEdges* const edges = resolution->edges.data();
  int arcs[2] = {0, 0};  // The holes' vertices on each piece.
  for (const HoleCrossing& c : path.holes) {
    arcs[0] += HoleArcSize(polygon, c.hole, c.leave, c.enter);
    arcs[1] += HoleArcSize(polygon, c.hole, c.enter, c.leave);
  }
  AppendOuterChain(polygon.outer, path.x, path.y, m, arcs[0], &pieces[0].outer,
                   &resolution->inherited[0], &edges[0]);
  for (int i = m - 1; i >= 0; --i) {
    const HoleCrossing& c = path.holes[i];
    AppendHoleChain(polygon, c.hole, c.leave, c.enter, i, &pieces[0].outer, &edges[0]);
  }
  AppendOuterChain(polygon.outer, path.y, path.x, 0, arcs[1], &pieces[1].outer,
                   &resolution->inherited[1], &edges[1]);
  for (int i = 0; i < m; ++i) {
    const HoleCrossing& c = path.holes[i];
    AppendHoleChain(polygon, c.hole, c.enter, c.leave, i + 1, &pieces[1].outer, &edges[1]);
  }
  std::vector<int> crossed;
  for (const HoleCrossing& c : path.holes) crossed.push_back(c.hole);
  DistributeHoles(polygon, crossed, resolution);
  resolution->cuts.clear();
  Point2d from = path.x.point;
  for (const HoleCrossing& c : path.holes) {
    resolution->cuts.push_back({from, polygon.holes[c.hole][c.enter]});
    from = polygon.holes[c.hole][c.leave];
  }
  resolution->cuts.push_back({from, path.y.point});
  resolution->witness = witness;
}

enum class WalkOutcome { kPath, kNoHoleCrossed, kShutIn, kNotNearest };

// The walk of ResolveHoleAlongPath() from hole h: one side from its vertex `start_a`, the other
// from `start_b`, each only ever ahead along `ahead_a` / `ahead_b` when given. kPath, with the
// path in `path`, when both sides reach the outer boundary and cross another hole. With
// `nearest_links`, kNotNearest when a link to a hole is longer than the link its start would
// make to the nearest visible point of any other ring.
WalkOutcome WalkThroughHoles(const Polygon2d& polygon, const EdgeQuery& grid, int h, int start_a,
                             int start_b, const Point2d* ahead_a, const Point2d* ahead_b,
                             HolePath* path, bool nearest_links = false) {
  const int k = static_cast<int>(polygon.holes.size());
  std::vector<char> crossed(k, 0);
  crossed[h] = 1;
  std::vector<std::pair<Point2d, Point2d>> cuts;  // Made so far, for the crossing test.
  std::optional<Endpoint> outer_end;              // The first side's end.
  // Links `from` (a vertex of a crossed hole) to the closest visible point not on a crossed
  // hole, crossing no cut made so far and, given `ahead`, lying ahead of `from` along it; an
  // outer end other than the first side's vertex or edge (AppendOuterChain() orders ends by
  // vertex and edge).
  // Per hole, its vertex farthest along `ahead` (-1: not found yet), where a walk leaves it.
  std::vector<int> hole_top;
  auto top_of = [&](int hole, const Point2d& ahead) {
    if (hole_top.empty()) hole_top.assign(k, -1);
    if (hole_top[hole] < 0) hole_top[hole] = FarthestAlong(polygon.holes[hole], ahead);
    return hole_top[hole];
  };
  auto link = [&](const Endpoint& from, const Point2d* ahead) -> std::optional<Endpoint> {
    auto accept = [&](const Endpoint& e) {
      if (ahead != nullptr) {
        // Ahead of `from`, and on a hole only below the hole's top: the walk leaves from there,
        // ahead of the cut that enters (left from a vertex behind that cut, it was shut in).
        if (!((e.point - from.point).dot(*ahead) > 0.0)) return false;
        if (e.ring >= 0) {
          const Point2d& top = polygon.holes[e.ring][top_of(e.ring, *ahead)];
          if (!(e.point.dot(*ahead) < top.dot(*ahead))) return false;
        }
      }
      if (e.ring < 0 && outer_end && e.index == outer_end->index &&
          e.on_edge == outer_end->on_edge) {
        return false;
      }
      for (const auto& [u, w] : cuts) {
        if (SegmentsMeet(u, w, from.point, e.point)) return false;
      }
      return IsClearCut(polygon, grid, from, e);
    };
    // Nearest first, ties by ring, index and kind; outer vertices and feet on outer edges.
    return grid.Nearest(
        from.point, [&](int hole) { return crossed[hole] != 0; }, accept);
  };
  // One side of the path, from vertex `start` of hole h to the outer boundary: the holes
  // crossed (entered at the vertex reached, left at `leave`) and the outer end.
  struct Side {
    std::vector<HoleCrossing> holes;
    Endpoint end;
  };
  bool not_nearest = false;
  auto walk = [&](int start, const Point2d* ahead, Side* side) {
    hole_top.clear();  // (Along this side's `ahead`.)
    Endpoint from{h, start, false, polygon.holes[h][start]};
    for (;;) {
      const std::optional<Endpoint> to = link(from, ahead);
      if (!to) return false;
      if (nearest_links && to->ring >= 0) {  // (A link to the outer ring ends the walk.)
        const int own = from.ring;
        const std::optional<Endpoint> nearest = grid.Nearest(
            from.point, [&](int hole) { return hole == own; },
            [&](const Endpoint& e) { return IsClearCut(polygon, grid, from, e); });
        if (nearest && (to->point - from.point).squaredNorm() >
                           (nearest->point - from.point).squaredNorm() * (1.0 + 1e-9)) {
          not_nearest = true;
          return false;
        }
      }
      cuts.emplace_back(from.point, to->point);
      if (to->ring < 0) {
        side->end = *to;
        outer_end = *to;
        return true;
      }
      // Left from its vertex farthest from the entry, or its top (the entry lies below it).
      const Ring2d& hole = polygon.holes[to->ring];
      int leave = to->index == 0 ? 1 : 0;
      if (ahead != nullptr) {
        leave = top_of(to->ring, *ahead);
      } else {
        for (int i = 0; i < static_cast<int>(hole.size()); ++i) {
          if ((hole[i] - to->point).squaredNorm() > (hole[leave] - to->point).squaredNorm()) {
            leave = i;
          }
        }
      }
      crossed[to->ring] = 1;
      side->holes.push_back({to->ring, to->index, leave});
      from = {to->ring, leave, false, hole[leave]};
    }
  };
  Side a, b;
  if (!walk(start_a, ahead_a, &a) || !walk(start_b, ahead_b, &b)) {
    return not_nearest ? WalkOutcome::kNotNearest : WalkOutcome::kShutIn;
  }
  if (a.holes.empty() && b.holes.empty()) return WalkOutcome::kNoHoleCrossed;
  // The path from a's end: side a's holes in reverse (entered where side a left them), h, b's.
  *path = {a.end, b.end, {}};
  for (auto it = a.holes.rbegin(); it != a.holes.rend(); ++it) {
    path->holes.push_back({it->hole, it->leave, it->enter});
  }
  path->holes.push_back({h, start_a, start_b});
  path->holes.insert(path->holes.end(), b.holes.begin(), b.holes.end());
  return WalkOutcome::kPath;
}

// Where a walk from hole h started (side a's first cut).
const Point2d& StartOf(const Polygon2d& polygon, const HolePath& path, int h) {
  const auto at_h = std::find_if(path.holes.begin(), path.holes.end(),
                                 [&](const HoleCrossing& c) { return c.hole == h; });
  return polygon.holes[h][at_h->enter];
}

// Resolves hole `h` the way Eqn. 4.2 ranks it: a hole is linked to the closest ring, which may
// be another hole (Fig. 23: holes behind holes), and once linked its deepest point is the
// antipode of the link (Fig. 19), which the next iteration would link in turn. Here both links
// are made at once: from p and from cw(p), each to the closest visible vertex (or outer edge
// point) not on a hole already crossed; a hole reached is left from its vertex farthest from
// where it was entered, again to the closest visible point, until the outer boundary is
// reached. The piece splits in two along this path and every hole on it is resolved by the one
// split: where holes lie closer to each other than to the outer boundary (cells separated by
// thin walls), the path crosses walls instead of running around them. Among many holes (a
// noisy occupancy grid) such a walk can curl round and shut itself in, and its failed search
// has offered every boundary point. Then both sides walk again, each only ever ahead, along
// p - cw(p) on p's side and back along it on cw(p)'s, starting from h's vertex farthest that
// way, entering each hole below its top and leaving it from its vertex farthest ahead: no link
// goes back past another, so no side shuts itself in (a hole one side crosses may still reach
// into the other's way). Returns false, leaving the choice to ResolveHole(), when no hole is
// reached or the path cannot be completed.
bool ResolveHoleAlongPath(const Polygon2d& polygon, const EdgeQuery& grid,
                          const Concavity2d& concavity, int h, Resolution* resolution) {
  if (polygon.holes.size() < 2) return false;
  const HoleConcavity& antipodes = concavity.holes[h];
  if (antipodes.p == antipodes.cw_p) return false;
  HolePath path;
  WalkOutcome outcome =
      WalkThroughHoles(polygon, grid, h, antipodes.p, antipodes.cw_p, nullptr, nullptr, &path);
  if (outcome == WalkOutcome::kShutIn) {
    // Along p - cw(p), from h's vertices farthest ahead and farthest behind: then h, too, lies
    // behind both sides (a hole curled round may reach past p and cw(p)).
    const Ring2d& ring = polygon.holes[h];
    const Point2d ahead = ring[antipodes.p] - ring[antipodes.cw_p];
    const Point2d behind = -ahead;
    outcome = WalkThroughHoles(polygon, grid, h, FarthestAlong(ring, ahead, antipodes.p),
                               FarthestAlong(ring, behind, antipodes.cw_p), &ahead, &behind, &path);
  }
  if (outcome != WalkOutcome::kPath) return false;
  SplitAlongPath(polygon, path, StartOf(polygon, path, h), resolution);
  return true;
}

// Whether a hole's split peels: one piece keeps fewer than an eighth of the holes, of at least
// eight (with fewer, peeling costs little).
bool PeelsHoles(const Polygon2d& polygon, const Resolution& resolution) {
  const size_t k = polygon.holes.size();
  const size_t fewer =
      std::min(resolution.pieces[0].holes.size(), resolution.pieces[1].holes.size());
  return k >= 8 && 8 * fewer < k;
}

// The unit direction the holes mostly run along: the principal axis of their vertices about
// their centres (each hole's own principal axis, as Ch. IV.A.2.b takes its antipodes along,
// summed), the leading eigenvector solved in closed form (no trigonometry, so the same on every
// platform); it turns with the polygon, up to its sign. The x axis when no way is longer.
Point2d HolesAxis(const Polygon2d& polygon, const std::vector<Point2d>& centres) {
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (int i = 0; i < static_cast<int>(polygon.holes.size()); ++i) {
    for (const Point2d& v : polygon.holes[i]) {
      const Point2d d = v - centres[i];
      xx += d.x() * d.x();
      xy += d.x() * d.y();
      yy += d.y() * d.y();
    }
  }
  const double half = 0.5 * (xx - yy);
  const double larger = 0.5 * (xx + yy) + std::sqrt(half * half + xy * xy);
  // Two forms of its eigenvector; the longer is the better conditioned.
  const Point2d u(xy, larger - xx), w(larger - yy, xy);
  const Point2d axis = u.squaredNorm() >= w.squaredNorm() ? u : w;
  const double norm = axis.norm();
  return norm > 0.0 ? Point2d(axis / norm) : Point2d(1.0, 0.0);
}

// Splits a piece with many holes in two along a walk through holes that divides them about
// evenly, for when resolving the witness hole peels (PeelsHoles()). Every hole outranks every
// outer notch (Eqn. 4.2's delta), so the order the holes are resolved in is ours to choose;
// peeling a few holes off a piece that keeps the others, again and again, measures that piece
// again each time: about H^2 / 4 hole measures for H holes where the chains of nearest holes
// that rank them (Fig. 23) are arbitrary, as in a regular grid of obstacles (a warehouse);
// halving makes it about H log H. The walk starts at the hole whose centre is the median across
// the axis the holes mostly run along (HolesAxis()) and goes both ways along that axis, only
// ever ahead (ResolveHoleAlongPath()'s second walk), as a hole's own cuts at p and cw(p) would:
// in a warehouse, along a row of shelves, leaving the aisles between rows whole. Each link
// between holes must be as short as the nearest link from its start, ahead or not: the gaps
// such a walk cuts are those Eqn. 4.2's chains cut; among irregular holes, where going ahead
// would take longer cuts, the witness's split stands. Across the axis if the walk along it
// cannot be made. False, with `resolution` as it was, when neither can.
bool HalveHoles(const Polygon2d& polygon, const EdgeQuery& grid, Resolution* resolution) {
  const int k = static_cast<int>(polygon.holes.size());
  std::vector<Point2d> centres(k);
  for (int i = 0; i < k; ++i) {
    centres[i] = Point2d::Zero();
    for (const Point2d& v : polygon.holes[i]) centres[i] += v;
    centres[i] /= static_cast<double>(polygon.holes[i].size());
  }
  // `d` or -d, whichever hole k - 1's centre lies no nearer along than hole 0's: a sign the
  // holes' order fixes, so that the walk turns and mirrors with the polygon.
  auto oriented = [&](const Point2d& d) {
    return centres[0].dot(d) <= centres[k - 1].dot(d) ? d : Point2d(-d);
  };
  const Point2d along = HolesAxis(polygon, centres);
  std::vector<double> across(k);
  std::vector<int> order(k);
  for (const Point2d& axis : {along, Point2d(-along.y(), along.x())}) {
    const Point2d ahead = oriented(axis), behind = -ahead;
    const Point2d normal = oriented(Point2d(-axis.y(), axis.x()));
    for (int i = 0; i < k; ++i) across[i] = centres[i].dot(normal);
    std::iota(order.begin(), order.end(), 0);
    // A total order (ties by index), so the median does not depend on the standard library.
    auto before = [&](int u, int v) {
      return across[u] != across[v] ? across[u] < across[v] : u < v;
    };
    std::nth_element(order.begin(), order.begin() + k / 2, order.end(), before);
    const int h = order[k / 2];
    const Ring2d& ring = polygon.holes[h];
    HolePath path;
    if (WalkThroughHoles(polygon, grid, h, FarthestAlong(ring, ahead), FarthestAlong(ring, behind),
                         &ahead, &behind, &path, /*nearest_links=*/true) == WalkOutcome::kPath) {
      SplitAlongPath(polygon, path, StartOf(polygon, path, h), resolution);
      return true;
    }
  }
  return false;
}

// Resolves hole `h`: connects its antipode p to the outer boundary (Algorithm 5) and, so that
// the piece splits in two, cuts at cw(p) too, the deepest point of the pocket the first cut
// makes (Fig. 19). Where an antipode sees no outer point (a hole wrapped around itself or
// hidden behind others), other hole vertices stand in: for the first cut, the ones nearest to
// the outer boundary; for the second, the ones farthest from the first.
bool ResolveHole(const Polygon2d& polygon, const EdgeQuery& grid, const Concavity2d& concavity,
                 int h, const ResolveOptions& options, Resolution* resolution) {
  const Ring2d& hole = polygon.holes[h];
  const int m = static_cast<int>(hole.size());
  const HoleConcavity& antipodes = concavity.holes[h];
  if (ResolveHoleAlongPath(polygon, grid, concavity, h, resolution)) return true;
  auto try_pair = [&](int a, int b, bool thorough, const Endpoint& x) {
    if (b == a) return false;
    const std::optional<Endpoint> y =
        SecondHoleCut(polygon, grid, concavity, h, a, x, b, thorough, options);
    if (y) SplitThroughHole(polygon, h, a, x, b, *y, resolution);
    return y.has_value();
  };
  auto try_first = [&](int a, int partner) {
    const std::optional<Endpoint> x = FirstHoleCut(polygon, grid, concavity, h, a, options);
    if (!x) return false;
    if (partner >= 0 && try_pair(a, partner, true, *x)) return true;
    std::vector<int> others(m);
    std::iota(others.begin(), others.end(), 0);
    std::sort(others.begin(), others.end(), [&](int u, int v) {  // Farthest first.
      const double du = (hole[u] - hole[a]).squaredNorm(), dv = (hole[v] - hole[a]).squaredNorm();
      return du != dv ? du > dv : u < v;
    });
    for (int b : others) {
      if (b != partner && try_pair(a, b, false, *x)) return true;
    }
    return false;
  };
  if (try_first(antipodes.p, antipodes.cw_p) || try_first(antipodes.cw_p, antipodes.p)) {
    return true;
  }
  std::vector<int> firsts(m);
  std::iota(firsts.begin(), firsts.end(), 0);
  std::vector<double> reach(m);
  for (int i = 0; i < m; ++i) {
    reach[i] = std::numeric_limits<double>::infinity();
    for (const Point2d& v : polygon.outer)
      reach[i] = std::min(reach[i], (v - hole[i]).squaredNorm());
  }
  std::sort(firsts.begin(), firsts.end(),
            [&](int u, int v) { return reach[u] != reach[v] ? reach[u] < reach[v] : u < v; });
  for (int a : firsts) {
    if (a != antipodes.p && a != antipodes.cw_p && try_first(a, -1)) return true;
  }
  return false;
}

}  // namespace

bool Resolve(const Polygon2d& polygon, const Concavity2d& concavity, const ResolveOptions& options,
             Resolution* resolution) {
  // Storage the thread keeps from one split to the next (a fresh grid's arrays came from memory
  // not touched lately); one Resolve() runs at a time per thread.
  thread_local RingBlocks outer_blocks;
  thread_local HoleBlocks hole_blocks;
  thread_local EdgeGrid grid_storage;
  const ScratchScope blocks_scope(outer_blocks);
  const ScratchScope hole_blocks_scope(hole_blocks);
  const ScratchScope grid_scope(grid_storage);
  outer_blocks.Assign(polygon.outer, &concavity.outer);
  const EdgeQuery grid(polygon, outer_blocks, &hole_blocks, &grid_storage);
  if (concavity.witness_hole >= 0) {
    // The witness hole first, then the others by decreasing concavity; each with either
    // antipode connecting first.
    std::vector<int> order(polygon.holes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return concavity.holes[a].concavity > concavity.holes[b].concavity;
    });
    std::stable_partition(order.begin(), order.end(),
                          [&](int k) { return k == concavity.witness_hole; });
    for (int k : order) {
      if (ResolveHole(polygon, grid, concavity, k, options, resolution)) {
        if (PeelsHoles(polygon, *resolution)) HalveHoles(polygon, grid, resolution);
        return true;
      }
    }
    return HalveHoles(polygon, grid, resolution);
  }
  // The witness; should no cut resolve it, the other outer notches by decreasing concavity.
  if (concavity.witness_vertex >= 0 &&
      ResolveOuterNotch(polygon, grid, concavity, concavity.witness_vertex, options, resolution)) {
    return true;
  }
  const Ring2d& outer = polygon.outer;
  const int n = static_cast<int>(outer.size());
  std::vector<int> notches;
  for (int i = 0; i < n; ++i) {
    if (i != concavity.witness_vertex && IsNotchAt(outer, i)) {
      notches.push_back(i);
    }
  }
  std::stable_sort(notches.begin(), notches.end(),
                   [&](int a, int b) { return concavity.outer[a] > concavity.outer[b]; });
  for (int r : notches) {
    if (ResolveOuterNotch(polygon, grid, concavity, r, options, resolution)) return true;
  }
  if (concavity.witness_vertex >= 0 &&
      ResolveOuterNotch(polygon, grid, concavity, concavity.witness_vertex, options, resolution,
                        /*last_resort=*/true)) {
    return true;
  }
  for (int r : notches) {
    if (ResolveOuterNotch(polygon, grid, concavity, r, options, resolution, /*last_resort=*/true)) {
      return true;
    }
  }
  return false;
}

}  // namespace acdplan::acd::internal
