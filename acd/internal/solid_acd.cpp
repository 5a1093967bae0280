#include "acd/internal/solid_acd.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "acd/internal/closed_shells.h"
#include "acd/internal/cut_plane.h"
#include "acd/internal/cut_topology.h"
#include "acd/internal/exact_plane_split.h"
#include "acd/internal/merge_components.h"
#include "acd/internal/solid_concavity.h"
#include "acd/internal/solid_openings.h"
#include "acd/internal/subtree.h"
#include "acd/mesh_measures.h"
#include "base/input_error.h"

namespace acdplan::acd::internal {
namespace {

// Safety cap on the pieces of one part (leaves plus pieces waiting to be cut), so that no input
// runs away (a tau far below the mesh's detail); pieces still waiting when it is reached become
// leaves as they are, and may exceed tau.
constexpr int kMaxPiecesPerPart = 2048;
// A cut leaving a piece below this fraction of the cut piece's volume is rejected.
constexpr double kMinPieceFraction = 1e-9;
// When no ranked plane cuts a piece cleanly, the planes are tried again moved along their
// normals by these fractions of tau, either way, nearest first. A plane through the witness
// vertex often passes exactly through other vertices too (a mesh stored in single precision,
// an axis plane), and gives a section that does not close, a plane tangent to the surface
// inside the section (SplitByPlane), or a piece whose rounded cut faces cross another face; a
// hair off it does not (measured: character at tau_rel 0.02, whose ranked planes all failed so,
// kept a piece 23 x tau deep without these). Farther shifts for where every plane near the
// witness fails; a pocket deeper than tau still meets a plane a quarter of tau off.
constexpr double kPlaneShifts[] = {1e-3, 0.05, 0.25};

struct Piece {
  ExactPiece exact;
  TriangleMesh mesh;  // the double copy: hulls, distances, volumes and scores
  SolidConcavity concavity;
  ShellTopology topology;
  int node = -1;
};

// A piece a cut made (or a whole part), with its double copy and its topology, each found once.
struct CutPiece {
  ExactPiece exact;
  TriangleMesh mesh;
  ShellTopology topology;
};

CutPiece WholePart(const TriangleMesh& part) {
  CutPiece out{ToExact(part), part, {}};
  out.topology = Topology(out.exact.triangles);
  return out;
}

Piece MakePiece(CutPiece cut, double tau) {
  Piece piece;
  piece.exact = std::move(cut.exact);
  piece.mesh = std::move(cut.mesh);
  piece.concavity = MeasureSolidConcavity(piece.mesh, tau);
  piece.topology = cut.topology;
  return piece;
}

// A piece is final when it is tau-convex (Algorithm 1) and a single shell of genus 0: a handle
// or a cavity is cut open even where it is shallow (Sec. V.C).
bool IsFinal(const Piece& piece, double tau) {
  return piece.concavity.value <= tau && piece.topology.genus == 0 && piece.topology.shells == 1;
}

// The pieces `piece` falls into when cut by `plane` (each half split into its connected solids).
// `*sliver` says whether one of them is a sliver (below kMinPieceFraction of their volume).
std::vector<CutPiece> Cut(const ExactPiece& piece, const Plane3d& plane, bool* sliver) {
  *sliver = false;
  const ExactKernel::Plane_3 exact(plane.normal.x(), plane.normal.y(), plane.normal.z(),
                                   -plane.offset);
  ExactPiece below, above;
  if (!SplitByPlane(piece, exact, &below, &above) || below.triangles.empty() ||
      above.triangles.empty()) {
    return {};
  }
  std::vector<ExactPiece> solids = ConnectedSolids(below);
  for (ExactPiece& p : ConnectedSolids(above)) solids.push_back(std::move(p));
  // A section the cap could not close cleanly (constraints that overlap or cross, which a
  // valid solid's section should not have) rejects the plane rather than leak an open piece;
  // so does a piece that is valid exactly but not once rounded to the doubles it is output as,
  // and a cavity that no outer shell of its half encloses (only a defect could leave one).
  // A plane that only shaves off a rounding-level sliver (a plane through a vertex whose
  // neighbours lie a hair off it) is flagged: such a piece would be a component of no use, so
  // the plane is taken only when no other splits the piece.
  std::vector<CutPiece> out;
  std::vector<double> volumes;
  double total = 0;
  const RoundedFaceSet faces_of_piece(piece);
  for (ExactPiece& p : solids) {
    const ShellTopology topology = Topology(p.triangles);
    if (!topology.closed || !RoundsToValidSolid(p, &faces_of_piece)) return {};
    TriangleMesh mesh = ToDouble(p);
    if (VolumeSign(mesh) < 0) return {};
    volumes.push_back(MeshVolume(mesh));
    total += volumes.back();
    out.push_back({std::move(p), std::move(mesh), topology});
  }
  for (double v : volumes) *sliver = *sliver || !(v > kMinPieceFraction * total);
  // Each piece goes on from its rounded coordinates, which RoundsToValidSolid has just found a
  // valid solid (and which the pieces share where they meet): exact cut points of cut points
  // grow without bound (measured: teapot at tau_rel 0.2 spent minutes in the section's
  // triangulation on rationals of deep cuts), while doubles keep every cut's arithmetic small.
  for (CutPiece& p : out) {
    ExactPiece& e = p.exact;
    for (size_t i = 0; i < e.points.size(); ++i) {
      e.points[i] = ExactKernel::Point_3(e.rounded[i].x(), e.rounded[i].y(), e.rounded[i].z());
    }
  }
  return out;
}

// Algorithm 1 on part `source`: pieces wait in a max-heap by concavity (ties: creation order),
// the most concave is resolved by one plane cut, its pieces are measured and pushed.
void DecomposePart(const TriangleMesh& part, int source, double tau, bool keep_internal,
                   bool feature_grouping, Decomposition3d* out, std::map<int, Component3d>* leaves,
                   std::map<int, Component3d>* internal_nodes) {
  std::vector<Piece> pieces;
  auto add_node = [&](Piece piece, int parent) {
    HierarchyNode3d node;
    node.concavity = piece.concavity.value;
    node.witness = piece.concavity.witness;
    node.parent = parent;
    node.depth = parent < 0 ? 0 : out->tree[static_cast<size_t>(parent)].depth + 1;
    piece.node = static_cast<int>(out->tree.size());
    if (parent >= 0) out->tree[static_cast<size_t>(parent)].children.push_back(piece.node);
    out->tree.push_back(node);
    pieces.push_back(std::move(piece));
    return static_cast<int>(pieces.size()) - 1;
  };
  const std::array<Eigen::Vector3d, 3> axes = PartAxes(part);
  const int root = add_node(MakePiece(WholePart(part), tau), -1);
  out->roots.push_back(pieces[static_cast<size_t>(root)].node);
  if (!(tau > 0) && pieces[static_cast<size_t>(root)].concavity.value > 0) {
    std::ostringstream message;
    message << "Decompose3d(): tau must be > 0 for a non-convex part (part " << source
            << " has concavity " << pieces[static_cast<size_t>(root)].concavity.value << ")";
    throw InputError(message.str());
  }
  using Key = std::tuple<double, int>;  // (concavity, -index): deepest first, then oldest
  std::priority_queue<Key> heap;
  int live = 1;  // leaves plus pieces waiting
  auto settle = [&](int index) {
    Piece& piece = pieces[static_cast<size_t>(index)];
    if (IsFinal(piece, tau)) {
      out->tree[static_cast<size_t>(piece.node)].component = -2;  // a leaf; numbered later
      (*leaves)[piece.node] = SolidComponent(piece.mesh, piece.concavity, source);
      piece.exact = {};
    } else {
      heap.emplace(piece.concavity.value, -index);
    }
  };
  settle(root);
  while (!heap.empty()) {
    const int index = -std::get<1>(heap.top());
    heap.pop();
    Piece& piece = pieces[static_cast<size_t>(index)];
    std::vector<CutPiece> parts;
    Plane3d chosen;
    if (live < kMaxPiecesPerPart) {
      // The best-ranked plane that splits; for a handle, the best one that lowers the genus.
      // If none does, the same planes moved off by kPlaneShifts x tau either way, farther
      // only while none splits: a plane through the witness vertex can leave a piece pinched
      // at a vertex, or one that self-intersects once its cut points are rounded, where a
      // plane beside it does not.
      std::vector<CutPiece> fallback, sliver_fallback;
      Plane3d fallback_plane, sliver_plane;
      size_t fallback_rank = 0, sliver_rank = 0;
      // Cuts along `plane`, the `rank`-th tried in rank order; keeps the result in `parts` when
      // it is the cut sought, else as a fallback (the best-ranked of each kind).
      auto try_plane = [&](const Plane3d& plane, size_t rank) {
        bool sliver = false;
        std::vector<CutPiece> result = Cut(piece.exact, plane, &sliver);
        if (result.size() < 2) return;
        if (sliver) {
          // Last resort: a sliver component beats a piece left above tau (e.g. a repaired
          // solid whose every witness plane crosses a lens where two sheets crossed).
          if (sliver_fallback.empty() || rank < sliver_rank) {
            sliver_fallback = std::move(result), sliver_plane = plane, sliver_rank = rank;
          }
          return;
        }
        if (piece.topology.genus == 0 && piece.topology.shells == 1) {
          parts = std::move(result);
          chosen = plane;
          return;
        }
        int genus = 0, shells = 0;
        for (const CutPiece& p : result) {
          genus += p.topology.genus;
          shells += p.topology.shells - 1;
        }
        if (genus < piece.topology.genus ||
            (genus == piece.topology.genus && shells < piece.topology.shells - 1)) {
          parts = std::move(result);
          chosen = plane;
          return;
        }
        if (fallback.empty() || rank < fallback_rank) {
          fallback = std::move(result), fallback_plane = plane, fallback_rank = rank;
        }
      };
      std::vector<Plane3d> caps;  // the cuts that made the piece
      for (int up = out->tree[static_cast<size_t>(piece.node)].parent; up >= 0;
           up = out->tree[static_cast<size_t>(up)].parent) {
        caps.push_back(out->tree[static_cast<size_t>(up)].cut);
      }
      CutPlaneRanking ranking(piece.mesh, piece.concavity, tau, caps, feature_grouping,
                              /*lazy=*/true, axes);
      std::vector<Plane3d> ranked;  // the ranked planes taken from `ranking`, best first
      const int genus = piece.topology.genus;
      if (genus == 0 || piece.topology.shells != 1) {
        while (parts.empty()) {
          const std::optional<ScoredPlane> next = ranking.Next();
          if (!next) break;
          ranked.push_back(next->plane);
          try_plane(next->plane, ranked.size() - 1);
        }
      } else {
        // A handle: the best-ranked plane that lowers the genus, else the best one that splits.
        // Exact cuts are costly and most planes leave the handle whole, so those predicted to
        // lower it are cut first, then the others in rank order up to the first that splits.
        while (const std::optional<ScoredPlane> next = ranking.Next()) {
          ranked.push_back(next->plane);
        }
        std::vector<char> tried(ranked.size(), 0);
        for (size_t i = 0; i < ranked.size() && parts.empty(); ++i) {
          const std::optional<CutTopology> predicted =
              PredictCutTopology(piece.mesh, genus, ranked[i]);
          if (!predicted || predicted->genus < genus) {
            tried[i] = 1;
            try_plane(ranked[i], i);
          }
        }
        for (size_t i = 0; i < ranked.size() && parts.empty(); ++i) {
          if (!fallback.empty() && fallback_rank < i) break;
          if (!tried[i]) try_plane(ranked[i], i);
        }
      }
      if (parts.empty() && fallback.empty()) {  // no unshifted plane splits it
        // Farther only while nothing splits; a sliver left by an unshifted plane still gets
        // the nearest shift.
        size_t rank = ranked.size();
        for (size_t k = 0; k < std::size(kPlaneShifts) && parts.empty(); ++k) {
          if (k > 0 && (!fallback.empty() || !sliver_fallback.empty())) break;
          for (const double shift : {kPlaneShifts[k] * tau, -kPlaneShifts[k] * tau}) {
            for (size_t i = 0; i < ranked.size() && parts.empty(); ++i) {
              Plane3d plane = ranked[i];
              plane.offset += shift;
              try_plane(plane, rank++);
            }
          }
        }
      }
      if (parts.empty() && !fallback.empty()) parts = std::move(fallback), chosen = fallback_plane;
      if (parts.empty() && !sliver_fallback.empty()) {
        parts = std::move(sliver_fallback), chosen = sliver_plane;
      }
    }
    if (parts.empty()) {  // no plane splits it, or the cap is reached: it stays as it is
      const int node = piece.node;
      out->tree[static_cast<size_t>(node)].component = -2;
      (*leaves)[node] = SolidComponent(piece.mesh, piece.concavity, source);
      piece.exact = {};
      continue;
    }
    const int node = piece.node;
    out->tree[static_cast<size_t>(node)].cut = chosen;
    piece.exact = {};
    if (keep_internal)
      (*internal_nodes)[node] = SolidComponent(piece.mesh, piece.concavity, source);
    piece.mesh = {};
    live += static_cast<int>(parts.size()) - 1;
    for (CutPiece& p : parts) settle(add_node(MakePiece(std::move(p), tau), node));
  }
}

// The max_hulls cap: walks the hierarchy back up (its levels of detail, Fig. 9), each time
// collapsing the internal node whose children are all leaves and whose piece's hull adds the
// least volume over its children's hulls, until at most `max_hulls` leaves remain (or only
// roots do). The collapsed node's own piece is the exact union of its children.
void CapHulls(int max_hulls, Decomposition3d* out, std::map<int, Component3d>* leaves,
              std::map<int, Component3d>* internal_nodes) {
  int count = static_cast<int>(leaves->size());
  while (count > max_hulls) {
    int best = -1;
    double best_added = 0;
    for (const auto& [x, merged] : *internal_nodes) {
      const HierarchyNode3d& node = out->tree[static_cast<size_t>(x)];
      if (node.component == -2) continue;  // collapsed already
      double children = 0;
      bool all_leaves = true;
      for (int c : node.children) {
        const auto it = leaves->find(c);
        if (it == leaves->end()) {
          all_leaves = false;
          break;
        }
        children += it->second.hull_volume;
      }
      if (!all_leaves) continue;
      const double added = merged.hull_volume - children;
      if (best < 0 || added < best_added) best = x, best_added = added;
    }
    if (best < 0) break;
    HierarchyNode3d& node = out->tree[static_cast<size_t>(best)];
    for (int c : node.children) leaves->erase(c);
    count -= static_cast<int>(node.children.size()) - 1;
    node.children.clear();
    node.cut = Plane3d{};
    node.component = -2;
    (*leaves)[best] = std::move(internal_nodes->at(best));
  }
  // Drop the nodes below collapsed ones, renumbering the rest in their order.
  std::vector<int> id(out->tree.size(), -1);
  std::vector<HierarchyNode3d> tree;
  std::vector<int> order;
  for (const int root : out->roots) {
    const std::vector<int> subtree = SubtreeDepthFirst(out->tree, root);
    order.insert(order.end(), subtree.begin(), subtree.end());
  }
  std::sort(order.begin(), order.end());
  for (int x : order)
    id[static_cast<size_t>(x)] = static_cast<int>(tree.size()),
    tree.push_back(out->tree[static_cast<size_t>(x)]);
  for (HierarchyNode3d& node : tree) {
    if (node.parent >= 0) node.parent = id[static_cast<size_t>(node.parent)];
    for (int& c : node.children) c = id[static_cast<size_t>(c)];
  }
  for (int& r : out->roots) r = id[static_cast<size_t>(r)];
  std::map<int, Component3d> renumbered;
  for (auto& [x, c] : *leaves) renumbered[id[static_cast<size_t>(x)]] = std::move(c);
  *leaves = std::move(renumbered);
  out->tree = std::move(tree);
}

}  // namespace

Decomposition3d DecomposeSolid(const PreparedMesh& prepared, double tau, int max_hulls,
                               bool feature_grouping, double merge_growth) {
  Decomposition3d out;
  out.tau = tau;
  out.max_hulls = max_hulls;
  std::map<int, Component3d> leaves, internal_nodes;  // by tree node
  // Each part in its canonical numbering: where candidates tie (a torus's witness is any of a
  // ring of equally deep vertices), index order settles them, and the file's numbering must
  // not (measured before: torus1 at tau_rel 0.05 gave 30 components as read, 47, 44 or 35
  // renumbered).
  for (size_t p = 0; p < prepared.parts.size(); ++p) {
    DecomposePart(CanonicallyNumbered(prepared.parts[p]), static_cast<int>(p), tau, max_hulls > 0,
                  feature_grouping, &out, &leaves, &internal_nodes);
  }
  if (max_hulls > 0) CapHulls(max_hulls, &out, &leaves, &internal_nodes);
  // Number the leaves in depth-first order of the tree.
  for (const int root : out.roots) {
    for (const int x : SubtreeDepthFirst(out.tree, root)) {
      HierarchyNode3d& node = out.tree[static_cast<size_t>(x)];
      if (node.component == -2) {
        node.component = static_cast<int>(out.components.size());
        out.components.push_back(std::move(leaves.at(x)));
      }
    }
  }
  // The merge pass needs only which components touch, and recomputes the openings if it merged.
  const bool merging = merge_growth >= 0;
  ComputeOpenings(&out, merging ? OpeningDetail::kAdjacency : OpeningDetail::kFull);
  if (MergeComponents(tau, merge_growth, &out) == 0 && merging) ComputeOpenings(&out);
  out.stats.vertices = static_cast<int>(prepared.mesh.vertices.rows());
  out.stats.triangles = static_cast<int>(prepared.mesh.triangles.rows());
  out.stats.components = static_cast<int>(out.components.size());
  for (const Component3d& c : out.components) {
    out.stats.volume += c.volume;
    out.stats.hull_volume += c.hull_volume;
    out.stats.max_concavity = std::max(out.stats.max_concavity, c.concavity);
  }
  out.stats.surface = false;
  return out;
}

}  // namespace acdplan::acd::internal
