#include "acd/prepare_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_sphere_of_points_d_traits_3.h>
#include <CGAL/Min_sphere_of_spheres_d.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>

#include "acd/internal/closed_shells.h"
#include "acd/internal/disjoint_sets.h"
#include "acd/internal/face_intersections.h"
#include "acd/internal/fill_holes.h"
#include "acd/internal/mesh_edges.h"
#include "acd/internal/separate_pinches.h"
#include "acd/internal/winding_union.h"
#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using internal::EdgeTable;
using internal::MeshEdge;

std::string At(const Eigen::Vector3d& p) {
  return "(" + FormatSignificant(p.x(), 15) + ", " + FormatSignificant(p.y(), 15) + ", " +
         FormatSignificant(p.z(), 15) + ")";
}

using internal::DisjointSets;

// The triangles `faces` of `mesh` (ascending) with their own compacted vertex list.
TriangleMesh ExtractFaces(const TriangleMesh& mesh, const std::vector<int>& faces) {
  std::vector<int> local(static_cast<size_t>(mesh.vertices.rows()), -1);
  std::vector<int> used;
  for (const int f : faces) {
    for (int k = 0; k < 3; ++k) used.push_back(mesh.triangles(f, k));
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<Eigen::Vector3d> vertices;
  for (const int v : used) {
    local[static_cast<size_t>(v)] = static_cast<int>(vertices.size());
    vertices.push_back(mesh.vertices.row(v).transpose());
  }
  std::vector<Eigen::Vector3i> triangles;
  for (const int f : faces) {
    triangles.emplace_back(local[static_cast<size_t>(mesh.triangles(f, 0))],
                           local[static_cast<size_t>(mesh.triangles(f, 1))],
                           local[static_cast<size_t>(mesh.triangles(f, 2))]);
  }
  return MakeTriangleMesh(vertices, triangles);
}

// ---------------------------------------------------------------------------------------------
// Cleaning.

struct Cleaned {
  TriangleMesh mesh;
  int merged = 0;                             // Vertices merged into another at the same position.
  int unreferenced = 0;                       // Distinct positions no kept triangle uses.
  int degenerate = 0, first_degenerate = -1;  // Triangles of the input.
  int duplicate = 0, first_duplicate = -1;
  // Per triangle of `mesh`: its copies in the input face both ways equally often (a two-sided
  // sheet, or an internal face two closed shells share), so their winding numbers cancel.
  std::vector<bool> opposed;
  int first_opposed = -1;  // A triangle of the input with such copies.
};

// Whether (a, b, c) is an even permutation of its corners in ascending order, i.e. faces the
// same way as the sorted triple.
bool IsEvenOrder(int a, int b, int c) { return ((a > b) + (a > c) + (b > c)) % 2 == 0; }

// Merges vertices at identical positions (exact comparison: -0 and 0 are one position), drops
// triangles with a repeated or three collinear corners (exact predicate) and repeats of a
// triangle (same three vertices, either orientation; the first is kept), then drops the
// vertices no triangle uses. Vertices keep their relative order, as do triangles.
Cleaned Clean(const TriangleMesh& in) {
  const int nv = static_cast<int>(in.vertices.rows());
  const int nf = static_cast<int>(in.triangles.rows());
  auto position = [&](int v) {
    return std::make_tuple(in.vertices(v, 0), in.vertices(v, 1), in.vertices(v, 2));
  };
  std::vector<int> order(static_cast<size_t>(nv));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto pa = position(a), pb = position(b);
    return pa < pb || (!(pb < pa) && a < b);
  });
  std::vector<int> representative(static_cast<size_t>(nv));
  Cleaned out;
  for (size_t i = 0; i < order.size(); ++i) {
    const int v = order[i];
    const bool same = i > 0 && !(position(order[i - 1]) < position(v));
    representative[static_cast<size_t>(v)] =
        same ? representative[static_cast<size_t>(order[i - 1])] : v;
    out.merged += same;
  }

  auto point = [&](int v) {
    return Epick::Point_3(in.vertices(v, 0), in.vertices(v, 1), in.vertices(v, 2));
  };
  std::vector<Eigen::Vector3i> kept;
  std::vector<int> kept_from;
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3i t(representative[static_cast<size_t>(in.triangles(f, 0))],
                            representative[static_cast<size_t>(in.triangles(f, 1))],
                            representative[static_cast<size_t>(in.triangles(f, 2))]);
    if (t(0) == t(1) || t(1) == t(2) || t(0) == t(2) ||
        CGAL::collinear(point(t(0)), point(t(1)), point(t(2)))) {
      if (out.degenerate++ == 0) out.first_degenerate = f;
      continue;
    }
    kept.push_back(t);
    kept_from.push_back(f);
  }

  std::vector<std::pair<std::array<int, 3>, int>> keys;
  keys.reserve(kept.size());
  for (size_t i = 0; i < kept.size(); ++i) {
    std::array<int, 3> key{kept[i](0), kept[i](1), kept[i](2)};
    std::sort(key.begin(), key.end());
    keys.emplace_back(key, static_cast<int>(i));
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> drop(kept.size(), false), opposed(kept.size(), false);
  for (size_t begin = 0, end = 0; begin < keys.size(); begin = end) {
    int winding = 0;  // Copies facing the sorted triple's way minus the others.
    for (end = begin; end < keys.size() && keys[end].first == keys[begin].first; ++end) {
      const Eigen::Vector3i& t = kept[static_cast<size_t>(keys[end].second)];
      winding += IsEvenOrder(t(0), t(1), t(2)) ? 1 : -1;
      if (end > begin) drop[static_cast<size_t>(keys[end].second)] = true;
    }
    opposed[static_cast<size_t>(keys[begin].second)] = winding == 0;
  }

  std::vector<int> index(static_cast<size_t>(nv), -1);
  for (size_t i = 0; i < kept.size(); ++i) {
    if (drop[i]) continue;
    for (int k = 0; k < 3; ++k) index[static_cast<size_t>(kept[i](k))] = 0;
  }
  std::vector<Eigen::Vector3d> vertices;
  for (int v = 0; v < nv; ++v) {
    if (index[static_cast<size_t>(v)] < 0) continue;
    index[static_cast<size_t>(v)] = static_cast<int>(vertices.size());
    vertices.push_back(in.vertices.row(v).transpose());
  }
  out.unreferenced = nv - out.merged - static_cast<int>(vertices.size());
  std::vector<Eigen::Vector3i> triangles;
  for (size_t i = 0; i < kept.size(); ++i) {
    if (drop[i]) {
      if (out.duplicate++ == 0) out.first_duplicate = kept_from[i];
      continue;
    }
    triangles.emplace_back(index[static_cast<size_t>(kept[i](0))],
                           index[static_cast<size_t>(kept[i](1))],
                           index[static_cast<size_t>(kept[i](2))]);
    out.opposed.push_back(opposed[i]);
    if (opposed[i] && out.first_opposed < 0) out.first_opposed = kept_from[i];
  }
  out.mesh = MakeTriangleMesh(vertices, triangles);
  return out;
}

// The cleaning's notes; `of` names the mesh the face numbers refer to. After a repair the
// vertex counts only reflect how the repaired mesh was assembled, so `vertices` leaves them out.
void NoteCleaning(const Cleaned& c, const std::string& of, bool vertices,
                  std::vector<std::string>* notes) {
  if (vertices && c.merged > 0) notes->push_back("merged " + Plural(c.merged, "duplicate vertex"));
  if (c.degenerate > 0) {
    notes->push_back("dropped " + Plural(c.degenerate, "degenerate face") + " (first: face " +
                     std::to_string(c.first_degenerate) + of + ")");
  }
  if (c.duplicate > 0) {
    notes->push_back("dropped " + Plural(c.duplicate, "duplicate face") + " (first: face " +
                     std::to_string(c.first_duplicate) + of + ")");
  }
  if (vertices && c.unreferenced > 0) {
    notes->push_back("dropped " + Plural(c.unreferenced, "unreferenced vertex"));
  }
}

// ---------------------------------------------------------------------------------------------
// Orientation, parts and diagnosis.

struct Diagnosis {
  TriangleMesh mesh;  // Oriented.
  EdgeTable edges;
  // Patches: triangles connected across edges with exactly two triangles, ascending, in order
  // of their lowest triangle.
  std::vector<std::vector<int>> patches;
  std::vector<bool> closed;                    // Per patch: no edge of it has 1 or 3+ triangles.
  std::vector<bool> orientable;                // Per patch.
  std::vector<std::pair<int, int>> crossings;  // IntersectingFacePairs().
  std::vector<std::vector<int>> parts;         // Triangles of each part, ascending.
  int cavities = 0;
  int flipped = 0;  // Triangles whose orientation changed.
  MeshDefects defects;
};

void FlipFace(TriangleMesh* mesh, int f) {
  std::swap(mesh->triangles(f, 1), mesh->triangles(f, 2));
}

// Orients each patch consistently (breadth first from its lowest triangle, which keeps its
// orientation) and each closed patch outward (exact volume sign).
void OrientPatches(Diagnosis* d) {
  TriangleMesh& mesh = d->mesh;
  const EdgeTable& table = d->edges;
  const int nf = static_cast<int>(mesh.triangles.rows());
  std::vector<char> flip(static_cast<size_t>(nf), 0), seen(static_cast<size_t>(nf), 0);
  d->orientable.assign(d->patches.size(), true);
  for (size_t p = 0; p < d->patches.size(); ++p) {
    std::vector<int> queue{d->patches[p][0]};
    seen[static_cast<size_t>(queue[0])] = 1;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int k = 0; k < 3; ++k) {
        const MeshEdge& e = table.edges[static_cast<size_t>(
            table.face_edges[static_cast<size_t>(f)][static_cast<size_t>(k)])];
        if (e.count != 2) continue;
        const int g = table.faces[static_cast<size_t>(e.first)] == f
                          ? table.faces[static_cast<size_t>(e.first + 1)]
                          : table.faces[static_cast<size_t>(e.first)];
        const bool f_forward =
            internal::RunsForward(mesh, f, e.a, e.b) != (flip[static_cast<size_t>(f)] != 0);
        // Consistent neighbours run along their shared edge in opposite directions.
        const char wanted = internal::RunsForward(mesh, g, e.a, e.b) == f_forward ? 1 : 0;
        if (!seen[static_cast<size_t>(g)]) {
          seen[static_cast<size_t>(g)] = 1;
          flip[static_cast<size_t>(g)] = wanted;
          queue.push_back(g);
        } else if (flip[static_cast<size_t>(g)] != wanted) {
          d->orientable[p] = false;
        }
      }
    }
  }
  for (int f = 0; f < nf; ++f) {
    if (flip[static_cast<size_t>(f)]) FlipFace(&mesh, f);
  }
  for (size_t p = 0; p < d->patches.size(); ++p) {
    if (!d->closed[p] || !d->orientable[p]) continue;
    if (internal::VolumeSign(mesh, d->patches[p]) < 0) {
      for (const int f : d->patches[p]) FlipFace(&mesh, f);
    }
  }
}

// Groups closed shells into solid parts: a shell inside an odd number of others is a cavity of
// the innermost shell around it, turned inward (dissertation Ch. V models solids bounded by
// several shells; a part keeps its cavities so that its volume is outer minus inner).
void GroupShells(Diagnosis* d) {
  const auto enclosing = internal::EnclosingShells(d->mesh, d->patches);
  const size_t count = d->patches.size();
  std::vector<int> owner(count, -1);  // The part's outer shell.
  for (size_t i = 0; i < count; ++i) {
    const size_t depth = enclosing[i].size();
    if (depth % 2 == 0) {
      owner[i] = static_cast<int>(i);
      continue;
    }
    // The enclosing shell that is itself enclosed depth - 1 times is the innermost.
    for (const int j : enclosing[i]) {
      if (enclosing[static_cast<size_t>(j)].size() + 1 == depth) owner[i] = j;
    }
    for (const int f : d->patches[i]) FlipFace(&d->mesh, f);
    ++d->cavities;
  }
  std::vector<int> part_of(count, -1);
  for (size_t i = 0; i < count; ++i) {
    if (owner[i] != static_cast<int>(i)) continue;
    part_of[i] = static_cast<int>(d->parts.size());
    d->parts.emplace_back();
  }
  for (size_t i = 0; i < count; ++i) {
    // owner is -1 only if the nesting is inconsistent (it is not, for shells that do not
    // cross); such a shell then stands as a part of its own.
    const int part = owner[i] >= 0 ? part_of[static_cast<size_t>(owner[i])] : -1;
    if (part < 0) {
      d->parts.push_back(d->patches[i]);
      continue;
    }
    auto& faces = d->parts[static_cast<size_t>(part)];
    faces.insert(faces.end(), d->patches[i].begin(), d->patches[i].end());
  }
  for (auto& faces : d->parts) std::sort(faces.begin(), faces.end());
}

Diagnosis Diagnose(const TriangleMesh& cleaned) {
  Diagnosis d;
  d.mesh = cleaned;
  d.edges = internal::BuildEdgeTable(d.mesh);
  const int nf = static_cast<int>(d.mesh.triangles.rows());
  DisjointSets sets(nf);
  for (const MeshEdge& e : d.edges.edges) {
    if (e.count == 2) {
      sets.Unite(d.edges.faces[static_cast<size_t>(e.first)],
                 d.edges.faces[static_cast<size_t>(e.first + 1)]);
    }
  }
  // A set's root is its lowest triangle, met first: patch_of[root] is set before its members.
  std::vector<int> patch_of(static_cast<size_t>(nf), -1);
  for (int f = 0; f < nf; ++f) {
    const int root = sets.Find(f);
    if (patch_of[static_cast<size_t>(root)] < 0) {
      patch_of[static_cast<size_t>(root)] = static_cast<int>(d.patches.size());
      d.patches.emplace_back();
    }
    patch_of[static_cast<size_t>(f)] = patch_of[static_cast<size_t>(root)];
    d.patches[static_cast<size_t>(patch_of[static_cast<size_t>(f)])].push_back(f);
  }
  d.closed.assign(d.patches.size(), true);
  const MeshEdge* first_boundary = nullptr;
  const MeshEdge* first_non_manifold = nullptr;
  for (const MeshEdge& e : d.edges.edges) {
    if (e.count == 2) continue;
    if (e.count == 1) {
      ++d.defects.boundary_edges;
      if (!first_boundary) first_boundary = &e;
    } else {
      ++d.defects.non_manifold_edges;
      if (!first_non_manifold) first_non_manifold = &e;
    }
    for (int i = 0; i < e.count; ++i) {
      d.closed[static_cast<size_t>(
          patch_of[static_cast<size_t>(d.edges.faces[static_cast<size_t>(e.first + i)])])] = false;
    }
  }
  OrientPatches(&d);
  d.crossings = internal::IntersectingFacePairs(d.mesh);
  d.defects.self_intersections = static_cast<int>(d.crossings.size());

  auto edge_message = [&](const MeshEdge& e) {
    const Eigen::Vector3d mid =
        (d.mesh.vertices.row(e.a) + d.mesh.vertices.row(e.b)).transpose() / 2;
    return "edge " + std::to_string(e.a) + "-" + std::to_string(e.b) + " at " + At(mid) + " has " +
           Plural(e.count, "face") + " (a solid's edges have exactly 2)";
  };
  if (first_boundary) {
    d.defects.first = edge_message(*first_boundary);
  } else if (first_non_manifold) {
    d.defects.first = edge_message(*first_non_manifold);
  } else if (!d.crossings.empty()) {
    const auto [f, g] = d.crossings.front();
    d.defects.first = "faces " + std::to_string(f) + " and " + std::to_string(g) +
                      " intersect at " + At(internal::FaceIntersectionPoint(d.mesh, f, g)) +
                      " (a solid's surface does not cross itself)";
  }

  if (d.defects.none()) {
    GroupShells(&d);
  } else {
    d.parts = d.patches;
  }
  for (int f = 0; f < nf; ++f) {
    d.flipped +=
        internal::RunsForward(cleaned, f, d.mesh.triangles(f, 0), d.mesh.triangles(f, 1)) ? 0 : 1;
  }
  return d;
}

// ---------------------------------------------------------------------------------------------
// Repair.

// `d`'s mesh without the triangles whose copies cancel (`cleaned.opposed`, `d` diagnosing
// `cleaned.mesh`): by the winding rule repair follows, a two-sided sheet bounds no volume and a
// face that two closed shells share back to back lies inside their union (lamp.obj's
// overlapping polygons, a CAD assembly's touching blocks). Cleaning alone keeps one copy, which
// leaves the sheet a surface to diagnose and decompose. Nothing when every triangle cancels.
std::optional<TriangleMesh> DropOpposedFaces(const Diagnosis& d, const Cleaned& cleaned,
                                             std::vector<std::string>* notes) {
  std::vector<int> faces;
  for (size_t f = 0; f < cleaned.opposed.size(); ++f) {
    if (!cleaned.opposed[f]) faces.push_back(static_cast<int>(f));
  }
  const size_t dropped = cleaned.opposed.size() - faces.size();
  if (dropped == 0 || faces.empty()) return std::nullopt;
  notes->push_back("repair: dropped " + Plural(dropped, "face") +
                   " given as often one way as the other (first: face " +
                   std::to_string(cleaned.first_opposed) + "), which bound no volume");
  return ExtractFaces(d.mesh, faces);
}

// Closes the holes of `d`'s mesh; returns the mesh with the new triangles.
TriangleMesh CloseHoles(const Diagnosis& d, std::vector<std::string>* notes) {
  const internal::HoleFilling filling = internal::FillHoles(d.mesh);
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index v = 0; v < d.mesh.vertices.rows(); ++v) {
    vertices.push_back(d.mesh.vertices.row(v).transpose());
  }
  std::vector<Eigen::Vector3i> triangles;
  for (Eigen::Index f = 0; f < d.mesh.triangles.rows(); ++f) {
    triangles.push_back(d.mesh.triangles.row(f).transpose());
  }
  triangles.insert(triangles.end(), filling.triangles.begin(), filling.triangles.end());
  if (filling.filled > 0) {
    notes->push_back("repair: filled " + Plural(filling.filled, "hole") + " with " +
                     Plural(filling.triangles.size(), "triangle"));
  }
  if (filling.failed > 0) {
    notes->push_back("repair: could not fill " + Plural(filling.failed, "hole") +
                     " (no triangulation, or a boundary that does not close)");
  }
  return MakeTriangleMesh(vertices, triangles);
}

// Why UniteByWinding() returned nothing.
constexpr char kNoWindingSolid[] =
    " (the winding rule left no surface, or no ray found a clear way out)";

// Replaces each group of closed shells that cross each other or themselves by the solid they
// bound by the positive winding rule (UniteByWinding), which is their union when none crosses
// itself. One method for both: CGAL's corefinement requires shells that do not cross
// themselves, and CGAL 5.5's autorefinement is experimental and not safe on untrusted input.
TriangleMesh UniteCrossingShells(const Diagnosis& d, std::vector<std::string>* notes) {
  const int count = static_cast<int>(d.patches.size());
  std::vector<int> patch_of(static_cast<size_t>(d.mesh.triangles.rows()));
  for (int p = 0; p < count; ++p) {
    for (const int f : d.patches[static_cast<size_t>(p)]) patch_of[static_cast<size_t>(f)] = p;
  }
  DisjointSets groups(count);
  std::vector<bool> crosses_itself(static_cast<size_t>(count), false);
  std::string first_self;
  for (const auto& [f, g] : d.crossings) {
    const int a = patch_of[static_cast<size_t>(f)], b = patch_of[static_cast<size_t>(g)];
    groups.Unite(a, b);
    if (a == b && !crosses_itself[static_cast<size_t>(a)]) {
      crosses_itself[static_cast<size_t>(a)] = true;
      if (first_self.empty()) {
        first_self = " (first: faces " + std::to_string(f) + " and " + std::to_string(g) + ")";
      }
    }
  }
  std::vector<std::vector<int>> members(static_cast<size_t>(count));
  for (int p = 0; p < count; ++p) members[static_cast<size_t>(groups.Find(p))].push_back(p);

  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index v = 0; v < d.mesh.vertices.rows(); ++v) {
    vertices.push_back(d.mesh.vertices.row(v).transpose());
  }
  std::vector<Eigen::Vector3i> triangles;
  int united_groups = 0, united_shells = 0, failed_groups = 0;
  int self_crossing = 0, failed_self_crossing = 0, pinches = 0, specks = 0;
  for (int root = 0; root < count; ++root) {
    const auto& group = members[static_cast<size_t>(root)];
    int self_crossing_here = 0;
    for (const int p : group) self_crossing_here += crosses_itself[static_cast<size_t>(p)];
    std::optional<internal::WindingUnion> united;
    if (self_crossing_here > 0 || group.size() >= 2) {
      std::vector<int> faces;
      for (const int p : group) {
        const auto& shell = d.patches[static_cast<size_t>(p)];
        faces.insert(faces.end(), shell.begin(), shell.end());
      }
      united = internal::UniteByWinding(d.mesh, faces, d.crossings);
      if (self_crossing_here > 0) {
        (united ? self_crossing : failed_self_crossing) += self_crossing_here;
      } else if (united) {
        ++united_groups;
        united_shells += static_cast<int>(group.size());
      } else {
        ++failed_groups;
      }
    }
    if (united) {
      pinches += united->pinches;
      specks += united->specks;
      const TriangleMesh& solid = united->mesh;
      const int offset = static_cast<int>(vertices.size());
      for (Eigen::Index v = 0; v < solid.vertices.rows(); ++v) {
        vertices.push_back(solid.vertices.row(v).transpose());
      }
      for (Eigen::Index f = 0; f < solid.triangles.rows(); ++f) {
        triangles.push_back(solid.triangles.row(f).transpose() + Eigen::Vector3i::Constant(offset));
      }
      continue;
    }
    for (const int p : group) {
      for (const int f : d.patches[static_cast<size_t>(p)]) {
        triangles.push_back(d.mesh.triangles.row(f).transpose());
      }
    }
  }
  if (united_groups > 0) {
    notes->push_back("repair: united " + Plural(united_shells, "crossing closed shell") + " into " +
                     Plural(united_groups, "solid"));
  }
  if (failed_groups > 0) {
    notes->push_back("repair: could not unite " + Plural(failed_groups, "group") +
                     " of crossing closed shells" + kNoWindingSolid);
  }
  if (self_crossing > 0) {
    notes->push_back("repair: replaced " + Plural(self_crossing, "shell") +
                     (self_crossing == 1 ? " that crosses itself" : " that cross themselves") +
                     first_self + " by the solid inside them (positive winding)");
  }
  if (pinches > 0) {
    notes->push_back("repair: separated the fans of " + Plural(pinches, "pinch vertex") +
                     " of the united solids by 1e-3 of their shortest edge");
  }
  if (specks > 0) {
    notes->push_back("repair: dropped " + Plural(specks, "shell") +
                     " of less than 1e-9 of its solid's volume");
  }
  if (failed_self_crossing > 0) {
    notes->push_back(
        "repair: could not unite " + Plural(failed_self_crossing, "shell") +
        (failed_self_crossing == 1 ? " that crosses itself" : " that cross themselves") +
        first_self + kNoWindingSolid);
  }
  return MakeTriangleMesh(vertices, triangles);
}

// Cleans `mesh` again after a repair (new triangles may repeat or flatten) and diagnoses it.
Diagnosis Recheck(const TriangleMesh& mesh, const std::string& where,
                  std::vector<std::string>* notes) {
  const Cleaned cleaned = Clean(mesh);
  NoteCleaning(cleaned, " of the repaired mesh", false, notes);
  if (cleaned.mesh.triangles.rows() == 0) {
    throw std::logic_error(where + ": repair left no triangle");  // Repairs only add volume.
  }
  return Diagnose(cleaned.mesh);
}

// The mesh's vertices and triangles as arrays, with each triangle's part.
struct PartArrays {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> part_of;
};
PartArrays ArraysOf(const Diagnosis& d) {
  PartArrays out;
  for (Eigen::Index v = 0; v < d.mesh.vertices.rows(); ++v) {
    out.vertices.push_back(d.mesh.vertices.row(v).transpose());
  }
  for (Eigen::Index f = 0; f < d.mesh.triangles.rows(); ++f) {
    out.triangles.push_back(
        {d.mesh.triangles(f, 0), d.mesh.triangles(f, 1), d.mesh.triangles(f, 2)});
  }
  out.part_of.assign(out.triangles.size(), -1);
  for (size_t p = 0; p < d.parts.size(); ++p) {
    for (const int f : d.parts[p]) out.part_of[static_cast<size_t>(f)] = static_cast<int>(p);
  }
  return out;
}

// A solid whose part meets itself at a vertex (a cavity touching the outer shell, two lobes of
// one part) is valid, but no cut can keep such a point as a vertex of two fans, and its
// components would not be 2-manifolds: each fan gets its own copy of the vertex, moved a hair
// (internal::SeparatePinches), and the mesh is diagnosed again. Vertices where different parts
// meet stay: each part is decomposed on its own. A pinch that is left (too small to separate in
// doubles) is a defect; the parts are then the patches, each closed one facing outward.
Diagnosis SeparatePinchesOfParts(Diagnosis d, const std::string& where,
                                 std::vector<std::string>* notes) {
  PartArrays a = ArraysOf(d);
  const internal::PinchSeparation separation =
      internal::SeparatePinches(&a.vertices, &a.triangles, a.part_of);
  if (separation.separated > 0) {
    notes->push_back("separated the fans of " + Plural(separation.separated, "pinch vertex") +
                     " where a part touches itself by 1e-3 of their shortest edge");
    std::vector<Eigen::Vector3i> faces;
    for (const auto& t : a.triangles) faces.emplace_back(t[0], t[1], t[2]);
    d = Recheck(MakeTriangleMesh(a.vertices, faces), where, notes);
    if (!d.defects.none()) return d;
    a = ArraysOf(d);
  } else if (separation.left == 0) {
    return d;
  }
  // What is left: pinches too small to separate, or made again where the recheck merged copies.
  int first = -1, fans_at_first = 0;
  d.defects.pinch_vertices =
      internal::CountPinches(a.triangles, a.vertices.size(), a.part_of, &first, &fans_at_first);
  if (first < 0) return d;
  d.defects.first = "vertex " + std::to_string(first) + " at " +
                    At(d.mesh.vertices.row(first).transpose()) + " is a pinch: the surface meets " +
                    "itself there in " + std::to_string(fans_at_first) + " fans of faces whose " +
                    "edges are too short to move them apart (a solid's surface is a 2-manifold)";
  OrientPatches(&d);  // Cavities outward again, as the patches of a mesh that is not a solid.
  d.parts = d.patches;
  d.cavities = 0;
  return d;
}

}  // namespace

PreparedMesh PrepareMesh(const TriangleMesh& mesh, const PrepareMeshOptions& options,
                         const std::string& where) {
  CheckTriangleMesh(mesh, where);
  PreparedMesh prepared;
  const Cleaned cleaned = Clean(mesh);
  if (cleaned.mesh.triangles.rows() == 0) {
    throw InputError(where + ": mesh has no face of positive area (all " +
                     Plural(mesh.triangles.rows(), "face") + " are degenerate)");
  }
  NoteCleaning(cleaned, "", true, &prepared.notes);
  Diagnosis d = Diagnose(cleaned.mesh);
  if (d.flipped > 0) {
    prepared.notes.push_back("reoriented " + Plural(d.flipped, "face") +
                             " (consistent across edges, closed shells outward" +
                             (d.cavities > 0 ? ", cavities inward)" : ")"));
  }
  if (options.repair && !d.defects.none()) {
    if (std::optional<TriangleMesh> mesh = DropOpposedFaces(d, cleaned, &prepared.notes)) {
      d = Recheck(*mesh, where, &prepared.notes);
    }
    if (d.defects.boundary_edges > 0) {
      d = Recheck(CloseHoles(d, &prepared.notes), where, &prepared.notes);
    }
    if (d.defects.boundary_edges == 0 && d.defects.non_manifold_edges == 0 &&
        d.defects.self_intersections > 0) {
      d = Recheck(UniteCrossingShells(d, &prepared.notes), where, &prepared.notes);
    }
    if (!d.defects.none()) {
      prepared.notes.push_back("repair: still not a solid: " + d.defects.first);
    }
  }
  if (d.defects.none()) d = SeparatePinchesOfParts(std::move(d), where, &prepared.notes);
  if (d.defects.none()) {
    prepared.notes.push_back("found " + Plural(d.parts.size(), "solid part") +
                             (d.cavities > 0 ? " with " + Plural(d.cavities, "cavity") : ""));
  } else {
    prepared.notes.push_back("found " + Plural(d.parts.size(), "surface patch") + ": " +
                             Plural(d.defects.boundary_edges, "boundary edge") + ", " +
                             Plural(d.defects.non_manifold_edges, "non-manifold edge") + ", " +
                             Plural(d.defects.self_intersections, "self-intersection") +
                             (d.defects.pinch_vertices > 0
                                  ? ", " + Plural(d.defects.pinch_vertices, "pinch vertex")
                                  : ""));
  }
  for (const auto& faces : d.parts) prepared.parts.push_back(ExtractFaces(d.mesh, faces));
  // Parts of a solid are closed; otherwise they are the patches.
  prepared.closed_parts = d.defects.none() ? std::vector<bool>(d.parts.size(), true) : d.closed;
  prepared.mesh = std::move(d.mesh);
  prepared.defects = std::move(d.defects);
  return prepared;
}

void RequireSolid(const PreparedMesh& prepared, const std::string& where) {
  if (prepared.solid()) return;
  const std::string what =
      prepared.defects.first.empty() ? "it has no part" : prepared.defects.first;
  throw InputError(where + ": not a solid: " + what +
                   " (use --repair to close holes and remove self-intersections, or --surface)");
}

double ReferenceRadius(const TriangleMesh& mesh) {
  using Traits = CGAL::Min_sphere_of_points_d_traits_3<Epick, double, CGAL::Tag_true>;
  std::vector<Epick::Point_3> points;
  points.reserve(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    points.emplace_back(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  }
  if (points.empty()) return 0;
  CGAL::Min_sphere_of_spheres_d<Traits> sphere(points.begin(), points.end());
  return CGAL::to_double(sphere.radius());
}

}  // namespace acdplan::acd
