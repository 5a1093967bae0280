#include "acd/internal/shortest_paths.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "acd/internal/exact_predicates.h"
#include "acd/internal/triangulate_ring.h"

namespace acdplan::acd::internal {
namespace {

std::string Str(const Point2d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

// Dual tree of a triangulation as half-edge twins: half-edge 3t + k is the edge
// (tri[t][k] -> tri[t][k+1]); twin[h] is the half-edge of the neighbouring triangle across it
// (traversed the other way), or -1 on the ring's boundary. O(n): diagonals are bucketed by their
// smaller endpoint and matched with a scratch array indexed by the larger one.
std::vector<int> BuildTwins(const std::vector<std::array<int, 3>>& tris, int n) {
  const int m = static_cast<int>(tris.size());
  std::vector<int> twin(3 * m, -1);
  auto is_ring_edge = [n](int u, int v) { return v == (u + 1) % n || u == (v + 1) % n; };
  std::vector<int> start(n + 1, 0);
  for (int h = 0; h < 3 * m; ++h) {
    const int u = tris[h / 3][h % 3], v = tris[h / 3][(h % 3 + 1) % 3];
    if (!is_ring_edge(u, v)) ++start[std::min(u, v) + 1];
  }
  for (int i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> items(start[n]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int h = 0; h < 3 * m; ++h) {
    const int u = tris[h / 3][h % 3], v = tris[h / 3][(h % 3 + 1) % 3];
    if (!is_ring_edge(u, v)) items[fill[std::min(u, v)]++] = h;
  }
  std::vector<int> open(n, -1);  // open[larger endpoint] = unmatched half-edge in this bucket.
  for (int u = 0; u < n; ++u) {
    for (int k = start[u]; k < start[u + 1]; ++k) {
      const int h = items[k];
      const int v = std::max(tris[h / 3][h % 3], tris[h / 3][(h % 3 + 1) % 3]);
      if (open[v] < 0) {
        open[v] = h;
      } else {
        twin[h] = open[v];
        twin[open[v]] = h;
        open[v] = -1;
      }
    }
    for (int k = start[u]; k < start[u + 1]; ++k) {
      const int h = items[k];
      open[std::max(tris[h / 3][h % 3], tris[h / 3][(h % 3 + 1) % 3])] = -1;
    }
  }
  return twin;
}

// The funnel algorithm (Lee & Preparata 1984; Guibas, Hershberger, Leven, Sharir & Tarjan
// 1987): a depth-first walk of the dual tree away from the source. Crossing the diagonal
// (L, R) the funnel is the vertex sequence f[lo..hi] = L, ..., apex, ..., R in one shared
// buffer: the two concave chains of the shortest paths from the apex to L and to R. The third
// vertex x of the next triangle hangs off the funnel vertex f[j] whose wedge contains it (binary
// search with exact orientation tests); the funnel then splits into f[lo..j], x (towards (L, x))
// and x, f[j..hi] (towards (x, R)). Each split writes x into one buffer slot, which is restored
// when the child's subtree is done, so no funnel is ever copied. O(n log n) after the
// triangulation.
class FunnelWalk {
 public:
  FunnelWalk(const Ring2d& ring, const std::vector<std::array<int, 3>>& tris,
             const std::vector<int>& twin, ShortestPathTree* tree)
      : ring_(ring), tris_(tris), twin_(twin), tree_(tree), visited_(tris.size(), 0) {
    const size_t slack = tris.size() + 4;  // A funnel grows by at most one slot per level.
    buffer_.assign(2 * slack + 4, -1);
    center_ = static_cast<int>(slack) + 1;
  }

  void MarkVisited(int tri) { visited_[tri] = 1; }

  // Walks every triangle beyond half-edge `h` of an already visited triangle, starting from the
  // funnel `funnel` (L, ..., apex, ..., R as seen from the far side) with apex funnel[apex].
  void WalkAcross(int h, const std::vector<int>& funnel, int apex) {
    if (twin_[h] < 0) return;
    const int lo = center_;
    for (size_t i = 0; i < funnel.size(); ++i) buffer_[lo + i] = funnel[i];
    const int hi = lo + static_cast<int>(funnel.size()) - 1;
    stack_.push_back({twin_[h], lo, hi, lo + apex, lo, funnel[0]});
    while (!stack_.empty()) {
      const Task task = stack_.back();
      stack_.pop_back();
      if (task.half_edge < 0) {  // Undo a write once the subtree that needed it is done.
        buffer_[task.write_pos] = task.write_value;
        continue;
      }
      Visit(task);
    }
  }

 private:
  struct Task {
    int half_edge;  ///< Entry half-edge (L -> R) of the triangle to visit; -1: a restore task.
    int lo, hi, apex;
    int write_pos, write_value;  ///< Buffer write to apply before visiting (and undo after).
  };

  const Point2d& At(int pos) const { return ring_[buffer_[pos]]; }

  void Visit(const Task& task) {
    stack_.push_back({-1, 0, 0, 0, task.write_pos, buffer_[task.write_pos]});
    buffer_[task.write_pos] = task.write_value;
    const int t = task.half_edge / 3;
    const int k = task.half_edge % 3;
    if (visited_[t]) return;
    visited_[t] = 1;
    const int x = tris_[t][(k + 2) % 3];
    const Point2d& px = ring_[x];
    const int lo = task.lo, hi = task.hi, apex = task.apex;
    int j = apex;
    if (apex > lo && Orientation(At(apex), At(apex - 1), px) > 0) {
      // Beyond the left chain: the first (outermost) edge f[j+1] -> f[j] that x is left of.
      int a = lo, b = apex - 1;
      while (a < b) {
        const int mid = (a + b) / 2;
        if (Orientation(At(mid + 1), At(mid), px) > 0) {
          b = mid;
        } else {
          a = mid + 1;
        }
      }
      j = a;
    } else if (apex < hi && Orientation(At(apex), At(apex + 1), px) < 0) {
      // Beyond the right chain: the last edge f[j-1] -> f[j] that x is right of.
      int a = apex + 1, b = hi;
      while (a < b) {
        const int mid = (a + b + 1) / 2;
        if (Orientation(At(mid - 1), At(mid), px) < 0) {
          a = mid;
        } else {
          b = mid - 1;
        }
      }
      j = a;
    }
    if (tree_->parent[x] == -2) {
      const int via = buffer_[j];
      tree_->parent[x] = via;
      tree_->distance[x] = tree_->distance[via] + (px - ring_[via]).norm();
    }
    // Children: across (R -> x) the funnel is x, f[j..hi]; across (x -> L) it is f[lo..j], x.
    const int to_right = 3 * t + (k + 1) % 3;
    const int to_left = 3 * t + (k + 2) % 3;
    if (twin_[to_right] >= 0) {
      stack_.push_back({twin_[to_right], j - 1, hi, std::max(apex, j), j - 1, x});
    }
    if (twin_[to_left] >= 0) {
      stack_.push_back({twin_[to_left], lo, j + 1, std::min(apex, j), j + 1, x});
    }
  }

  const Ring2d& ring_;
  const std::vector<std::array<int, 3>>& tris_;
  const std::vector<int>& twin_;
  ShortestPathTree* tree_;
  std::vector<uint8_t> visited_;
  std::vector<int> buffer_;
  int center_ = 0;
  std::vector<Task> stack_;
};

}  // namespace

ShortestPathTree ComputeShortestPathTree(const Ring2d& ring, int source) {
  const int n = static_cast<int>(ring.size());
  if (n < 3) {
    throw std::invalid_argument(
        "ComputeShortestPathTree(): the ring needs at least 3 vertices, got " + std::to_string(n));
  }
  if (source < 0 || source >= n) {
    throw std::invalid_argument("ComputeShortestPathTree(): source " + std::to_string(source) +
                                " is not a vertex index in [0, " + std::to_string(n) + ")");
  }
  if (SignedArea(ring) < 0.0) {
    throw std::invalid_argument(
        "ComputeShortestPathTree(): the ring must be counter-clockwise, its signed area is " +
        std::to_string(SignedArea(ring)));
  }
  const std::vector<std::array<int, 3>> tris = TriangulateRing(ring);
  const std::vector<int> twin = BuildTwins(tris, n);

  ShortestPathTree tree;
  tree.parent.assign(n, -2);  // -2: not reached yet.
  tree.distance.assign(n, 0.0);
  tree.parent[source] = -1;

  // Root: a triangle (s, u, w) incident to the source; u and w see s directly.
  int root = 0, slot = 0;
  for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (tris[t][k] == source) {
        root = t;
        slot = k;
        t = static_cast<int>(tris.size());
        break;
      }
    }
  }
  const int u = tris[root][(slot + 1) % 3];
  const int w = tris[root][(slot + 2) % 3];
  for (int v : {u, w}) {
    if (tree.parent[v] == -2) {
      tree.parent[v] = source;
      tree.distance[v] = (ring[v] - ring[source]).norm();
    }
  }
  FunnelWalk walk(ring, tris, twin, &tree);
  walk.MarkVisited(root);
  // Seen from beyond each edge of the root, the funnel is (L, ..., R) with the apex at s.
  walk.WalkAcross(3 * root + slot, {u, source}, 1);               // Across s -> u.
  walk.WalkAcross(3 * root + (slot + 1) % 3, {w, source, u}, 1);  // Across u -> w.
  walk.WalkAcross(3 * root + (slot + 2) % 3, {source, w}, 0);     // Across w -> s.

  for (int v = 0; v < n; ++v) {
    if (tree.parent[v] == -2) {  // Unreachable only if the ring is not a (weakly) simple polygon.
      throw std::invalid_argument("ComputeShortestPathTree(): vertex " + std::to_string(v) + " " +
                                  Str(ring[v]) + " is not reachable; is the ring simple?");
    }
  }
  return tree;
}

// Distances to the bridge SEGMENT through one single-source tree (our derivation; it replaces
// the split into P_rho_beta-, P_rho_beta, P_rho_beta+ of Algorithm 2 but gives the same paths).
//
// Close the chain with an extra apex s = bridge midpoint + H * n_out, n_out the unit normal of
// the bridge pointing away from the pocket and H = 1e6 * (chain diameter). The ring
// (chain..., s) is simple: the two new edges lie in the open half-plane beyond the bridge line
// except at beta- and beta+, where no other chain vertex is. Its polygon is P_rho plus the
// triangle T = (beta-, beta+, s), and any path from s to a pocket vertex v crosses the bridge
// once, at a point p, after a straight leg inside the convex T. Hence
//   d_s(v) = min over p in bridge of |s - p| + d_P_rho(p, v),
// and |s - p| = sqrt(H^2 + t^2) = H + O(L^2 / H) for p at offset t along the bridge (|t| <= L/2):
// the first leg costs the same H + O(L^2/H) wherever it crosses, so the tree from s minimises
// d_P_rho(p, v) over p, i.e. it holds the shortest paths to the segment (up to O(L^2/H) ties).
// For a vertex v whose tree parent is s the last leg is straight from v to s; its direction
// differs from n_out by at most L/H, i.e. in the limit H -> inf it is the perpendicular from v
// to the bridge, and its length beyond the crossing point is the distance from v to the bridge
// line, which we use exactly. When the optimal p is beta- or beta+ (Lemma A.2: v lies in
// P_rho_beta- or P_rho_beta+, or its perpendicular is blocked), the straight leg from s would
// leave P_rho + T, so the path bends at the end: beta-/beta+ are vertices of the ring, the
// funnel makes them the tree parent and the path ends there with distance 0. All other vertices
// take d(v) = |v - parent(v)| + d(parent(v)), summed in tree order, which avoids the
// cancellation of subtracting H from the tree's own distances.
std::vector<double> ShortestPathsToBridge(const Ring2d& chain) {
  const int m = static_cast<int>(chain.size());
  if (m < 2) {
    throw std::invalid_argument(
        "ShortestPathsToBridge(): the chain needs at least 2 vertices, got " + std::to_string(m));
  }
  const Point2d& beta_minus = chain.front();
  const Point2d& beta_plus = chain.back();
  if (beta_minus == beta_plus) {
    throw std::invalid_argument(
        "ShortestPathsToBridge(): the bridge has zero length, both ends at " + Str(beta_minus));
  }
  std::vector<double> result(m, 0.0);
  if (m == 2) return result;

  // The side of beta- -> beta+ the chain lies on: right (-1) for a counter-clockwise pocket
  // ring, whose interior is on the right of the bridge. Taken by the exact orientation of the
  // first vertex off the bridge line, not by the sign of the ring's area, which underflows to 0
  // for a pocket of subnormal coordinates (fuzz_decompose2d).
  int pocket_side = 0;
  for (int k = 1; k + 1 < m && pocket_side == 0; ++k) {
    pocket_side = Orientation(beta_minus, beta_plus, chain[k]);
  }
  if (pocket_side == 0) {
    throw std::invalid_argument("ShortestPathsToBridge(): the pocket polygon has zero area");
  }
  for (int k = 1; k + 1 < m; ++k) {
    if (Orientation(beta_minus, beta_plus, chain[k]) == -pocket_side) {
      throw std::invalid_argument("ShortestPathsToBridge(): chain vertex " + std::to_string(k) +
                                  " " + Str(chain[k]) +
                                  " lies beyond the bridge line, on the far side of the pocket");
    }
  }
  const Point2d along = (beta_plus - beta_minus).normalized();
  const Point2d left(-along.y(), along.x());
  Point2d lower = chain[0], upper = chain[0];
  for (const Point2d& p : chain) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  const double height = 1e6 * (upper - lower).norm();
  const Point2d apex = 0.5 * (beta_minus + beta_plus) - (pocket_side * height) * left;

  // The closed ring must be counter-clockwise: reverse it with the chain when the pocket is CW.
  Ring2d ring;
  ring.reserve(m + 1);
  std::vector<int> chain_of(m + 1, -1);  // Ring index -> chain index (-1 for the apex).
  int apex_index;
  if (pocket_side < 0) {  // Counter-clockwise already.
    ring = chain;
    for (int k = 0; k < m; ++k) chain_of[k] = k;
    ring.push_back(apex);
    apex_index = m;
  } else {
    ring.push_back(apex);
    for (int k = m - 1; k >= 0; --k) {
      chain_of[ring.size()] = k;
      ring.push_back(chain[k]);
    }
    apex_index = 0;
  }
  const ShortestPathTree tree = ComputeShortestPathTree(ring, apex_index);

  std::vector<uint8_t> done(m + 1, 0);
  std::vector<double> dist(m + 1, 0.0);
  done[apex_index] = 1;
  for (int r = 0; r <= m; ++r) {
    if (chain_of[r] == 0 || chain_of[r] == m - 1) done[r] = 1;  // The bridge ends: 0.
  }
  std::vector<int> pending;
  for (int start = 0; start <= m; ++start) {
    for (int v = start; !done[v]; v = tree.parent[v]) {
      if (tree.parent[v] == apex_index) {  // Straight, perpendicular last leg to the bridge.
        dist[v] = std::abs(left.dot(ring[v] - beta_minus));
        done[v] = 1;
        break;
      }
      pending.push_back(v);
    }
    while (!pending.empty()) {
      const int v = pending.back();
      pending.pop_back();
      const int up = tree.parent[v];
      dist[v] = dist[up] + (ring[v] - ring[up]).norm();
      done[v] = 1;
    }
  }
  for (int r = 0; r <= m; ++r) {
    if (chain_of[r] >= 0) result[chain_of[r]] = dist[r];
  }
  result.front() = 0.0;
  result.back() = 0.0;
  return result;
}

}  // namespace acdplan::acd::internal
