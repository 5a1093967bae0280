#include "acd/decompose2d.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "acd/concavity.h"
#include "acd/internal/centroid_area.h"
#include "acd/internal/openings.h"
#include "acd/internal/pocket_cache.h"
#include "acd/internal/resolve.h"
#include "base/input_error.h"
#include "base/stopwatch.h"

namespace acdplan::acd {
namespace {

void ValidateOptions(const Decompose2dOptions& options) {
  auto fail = [](const std::string& what) { throw InputError("Decompose2d(): " + what); };
  if (!(options.tau >= 0.0) || !std::isfinite(options.tau)) {
    fail("tau must be a finite number >= 0, got " + std::to_string(options.tau));
  }
  if (!(options.min_convexity >= 0.0 && options.min_convexity <= 1.0)) {
    fail("min_convexity must be in [0, 1], got " + std::to_string(options.min_convexity));
  }
  if (!(options.score_concavity >= 0.0) || !std::isfinite(options.score_concavity)) {
    fail("score_concavity must be >= 0");
  }
  if (!(options.score_distance > 0.0) || !std::isfinite(options.score_distance)) {
    fail("score_distance must be > 0");
  }
}

Ring2d HullOf(const Ring2d& ring, const std::vector<int>& indices) {
  Ring2d hull;
  hull.reserve(indices.size());
  for (int i : indices) hull.push_back(ring[i]);
  return hull;
}

// Whether a piece is final: Algorithm 1's concavity test, or Algorithm 9's convexity test.
bool IsAccepted(const Polygon2d& piece, const Concavity2d& concavity,
                const Decompose2dOptions& options) {
  const bool convex = concavity.witness_vertex < 0 && concavity.witness_hole < 0;
  if (convex) return true;
  if (options.min_convexity > 0.0) {
    return Area(piece) >=
           options.min_convexity * std::abs(SignedArea(HullOf(piece.outer, concavity.hull)));
  }
  // tau == 0 asks for convex pieces; a notch always has positive concavity (Lemma C.1).
  return options.tau > 0.0 && concavity.value <= options.tau;
}

// The most concave point of `piece`: its witness notch, or the antipode p of its witness hole;
// the first vertex of a convex piece.
Point2d WitnessPoint(const Polygon2d& piece, const Concavity2d& concavity) {
  if (concavity.witness_vertex >= 0) return piece.outer[concavity.witness_vertex];
  if (concavity.witness_hole >= 0) {
    return piece.holes[concavity.witness_hole][concavity.holes[concavity.witness_hole].p];
  }
  return piece.outer.front();
}

// What Decompose2d() keeps of the leaves besides their Component2d: per leaf its area, for the
// statistics, and its outer edges on cuts, for the openings (FindOpenings()).
struct LeafExtras {
  std::vector<double> areas;
  std::vector<internal::CutEdge> cut_edges;
  std::vector<int> first_cut_edge{0};
};

// Appends to `buffer` the outer edges on cuts of a piece cut from node `id`, by edge: those of
// the parent (buffer[parent_begin, parent_end), of a ring of `parent_n` vertices) that it keeps,
// then the cuts' own. (By index: appending may move the parent's.)
void AppendPieceCutEdges(int parent_begin, int parent_end, int parent_n, int id,
                         const internal::PieceEdges& edges,
                         std::vector<internal::CutEdge>* buffer) {
  const int f = edges.first_outer_edge;
  // The piece's edge t lies on the parent's edge f + t (cyclically): in the piece's order, the
  // parent's edges from f on, then those before f.
  for (const bool before_f : {false, true}) {
    for (int j = parent_begin; j < parent_end; ++j) {
      const internal::CutEdge e = (*buffer)[j];
      if ((e.edge < f) != before_f) continue;
      const int t = before_f ? e.edge + parent_n - f : e.edge - f;
      if (t < edges.outer_count) buffer->push_back({t, e.node, e.cut});
    }
  }
  for (const auto& [edge, cut] : edges.cuts) buffer->push_back({edge, id, cut});
}

// Room for `extra` more elements in `v`, growing it geometrically: an exact reserve per input
// polygon would copy the whole vector for each of them (quadratic in the number of polygons).
template <class T>
void ReserveMore(std::vector<T>* v, size_t extra) {
  const size_t needed = v->size() + extra;
  if (needed > v->capacity()) v->reserve(std::max(needed, 2 * v->capacity()));
}

// Algorithm 1 (or 9) on one input polygon, appending its nodes and leaves to `out` and what
// else is kept of the leaves to `leaves`.
void DecomposeOne(const Polygon2d& polygon, int source, const Decompose2dOptions& options,
                  Decomposition2d* out, LeafExtras* leaves) {
  const ConcavityOptions measure{options.measure, options.hole_diameter, options.tau};
  internal::ResolveOptions resolve;
  resolve.score_concavity = options.score_concavity;
  resolve.score_distance = options.score_distance;
  const double radius = ReferenceRadius(polygon);
  if (radius > 0.0) resolve.concavity_unit = radius / 100.0;
  resolve.steiner_cuts = options.steiner_cuts;
  resolve.tau = options.min_convexity > 0.0 ? 0.0 : options.tau;
  resolve.double_resolves_first = options.tau == 0.0 && options.min_convexity == 0.0;
  const int root = static_cast<int>(out->tree.size());
  // Each resolution removes a notch or a hole and creates no new ones but rounding-level
  // vertices on edges, so the number of splits is bounded by notches + holes (Theorem C.4):
  // room for that many nodes and leaves, so that the tree is not copied as it grows.
  const int notches = CountNotches(polygon);
  out->stats.notches += notches;
  const size_t splits_bound = static_cast<size_t>(notches) + polygon.holes.size();
  ReserveMore(&out->tree, 2 * splits_bound + 1);
  ReserveMore(&out->components, splits_bound + 1);
  ReserveMore(&leaves->areas, splits_bound + 1);
  ReserveMore(&leaves->first_cut_edge, splits_bound + 1);
  out->roots.push_back(root);
  out->tree.push_back({});
  out->tree[root].piece = polygon;
  const long budget = 4L * (VertexCount(polygon) + static_cast<long>(polygon.holes.size())) + 16;
  long splits = 0;
  internal::PocketCache cache;
  // Pieces waiting to be resolved, depth first, with their measures, the searches behind their
  // holes' links and their edges on cuts: a piece is measured when it is cut from its parent,
  // while the parent's measure is at hand to reuse (MeasureChildConcavity()). The edges on cuts
  // of all of them lie in one buffer, a range each, in stack order (the top piece's last).
  struct Pending {
    int id;
    Concavity2d concavity;
    std::vector<internal::HoleNeighbours> neighbours;
    int cut_edges_begin = 0, cut_edges_end = 0;
  };
  std::vector<internal::CutEdge> cut_edges;
  std::vector<Pending> stack(1);
  stack[0].id = root;
  stack[0].concavity =
      internal::MeasureConcavityCached(polygon, measure, &cache, &stack[0].neighbours);
  // Measures done with: their storage serves the next pieces' (as many are done with as made).
  std::vector<Concavity2d> spares;
  std::vector<Ring2d> spare_rings;  // Likewise the outer rings of pieces split.
  // Kept for the storage of what it holds besides the pieces.
  internal::Resolution resolution;
  while (!stack.empty()) {
    const int id = stack.back().id;
    Concavity2d concavity = std::move(stack.back().concavity);
    const std::vector<internal::HoleNeighbours> neighbours = std::move(stack.back().neighbours);
    const int begin = stack.back().cut_edges_begin, end = stack.back().cut_edges_end;
    stack.pop_back();
    out->tree[id].concavity = concavity.value;
    if (IsAccepted(out->tree[id].piece, concavity, options)) {
      HierarchyNode2d& node = out->tree[id];
      node.component = static_cast<int>(out->components.size());
      node.witness = WitnessPoint(node.piece, concavity);
      double area = 0.0;
      const Point2d centroid = internal::CentroidAndArea(node.piece, &area);
      leaves->areas.push_back(area);
      leaves->cut_edges.insert(leaves->cut_edges.end(), cut_edges.begin() + begin,
                               cut_edges.begin() + end);
      leaves->first_cut_edge.push_back(static_cast<int>(leaves->cut_edges.size()));
      cut_edges.resize(begin);
      Ring2d hull = HullOf(node.piece.outer, concavity.hull);
      out->components.push_back(
          {options.keep_pieces || id == root ? node.piece : std::move(node.piece), std::move(hull),
           centroid, concavity.value, source});
      spares.push_back(std::move(concavity));
      continue;
    }
    for (Polygon2d& piece : resolution.pieces) {
      if (spare_rings.empty()) break;
      piece.outer = std::move(spare_rings.back());
      spare_rings.pop_back();
    }
    if (++splits > budget || !Resolve(out->tree[id].piece, concavity, resolve, &resolution)) {
      std::ostringstream message;
      message << "Decompose2d(): could not resolve a piece with "
              << VertexCount(out->tree[id].piece) << " vertices and concavity " << concavity.value
              << " (split " << splits << ")";
      throw std::logic_error(message.str());
    }
    out->tree[id].witness = resolution.witness;
    out->tree[id].cuts = std::move(resolution.cuts);
    for (int side = 1; side >= 0; --side) {  // Child 0 is processed first (depth-first order).
      const int child = static_cast<int>(out->tree.size());
      Concavity2d* spare = spares.empty() ? nullptr : &spares.back();
      Pending& pending = stack.emplace_back();
      pending.id = child;
      pending.concavity = internal::MeasureChildConcavity(
          resolution.pieces[side], resolution.inherited[side], out->tree[id].piece.outer, concavity,
          measure, &cache, spare, {&neighbours, &resolution.hole_origins[side]},
          &pending.neighbours);
      if (spare != nullptr) spares.pop_back();
      pending.cut_edges_begin = static_cast<int>(cut_edges.size());
      AppendPieceCutEdges(begin, end, static_cast<int>(out->tree[id].piece.outer.size()), id,
                          resolution.edges[side], &cut_edges);
      pending.cut_edges_end = static_cast<int>(cut_edges.size());
      HierarchyNode2d node;
      node.piece = std::move(resolution.pieces[side]);
      node.parent = id;
      node.depth = out->tree[id].depth + 1;
      out->tree.push_back(std::move(node));
      out->tree[id].children[side] = child;
    }
    if (!options.keep_pieces && id != root) {
      spare_rings.push_back(std::move(out->tree[id].piece.outer));
      out->tree[id].piece = Polygon2d{};
    }
    // The children's edges on cuts take the place of the parent's.
    cut_edges.erase(cut_edges.begin() + begin, cut_edges.begin() + end);
    for (size_t k = stack.size() - 2; k < stack.size(); ++k) {
      stack[k].cut_edges_begin -= end - begin;
      stack[k].cut_edges_end -= end - begin;
    }
    spares.push_back(std::move(concavity));
  }
}

}  // namespace

Decomposition2d Decompose2d(const std::vector<Polygon2d>& polygons,
                            const Decompose2dOptions& options) {
  ValidateOptions(options);
  Decomposition2d out;
  out.measure = options.measure;
  out.tau = options.tau;
  out.min_convexity = options.min_convexity;
  const Stopwatch stopwatch;
  LeafExtras leaves;
  for (int i = 0; i < static_cast<int>(polygons.size()); ++i) {
    DecomposeOne(polygons[i], i, options, &out, &leaves);
  }
  out.openings = internal::FindOpenings(out, leaves.cut_edges, leaves.first_cut_edge,
                                        internal::FindSeams(polygons));
  out.stats.time_ms = stopwatch.Milliseconds();

  double area = 0.0, hull_area = 0.0;
  for (size_t k = 0; k < out.components.size(); ++k) {
    const Component2d& c = out.components[k];
    area += leaves.areas[k];
    hull_area += std::abs(SignedArea(c.hull));
    out.stats.max_concavity = std::max(out.stats.max_concavity, c.concavity);
  }
  out.stats.convexity = hull_area > 0.0 ? area / hull_area : 1.0;  // Eqn. 4.4.
  out.stats.components = static_cast<int>(out.components.size());
  for (const Polygon2d& p : polygons) out.stats.vertices += VertexCount(p);
  return out;
}

Decomposition2d Decompose2d(const Polygon2d& polygon, const Decompose2dOptions& options) {
  return Decompose2d(std::vector<Polygon2d>{polygon}, options);
}

}  // namespace acdplan::acd
