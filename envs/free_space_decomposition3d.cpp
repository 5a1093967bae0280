#include "envs/free_space_decomposition3d.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "acd/concavity.h"
#include "acd/decompose3d.h"
#include "acd/prepare_mesh.h"
#include "base/file_io.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "envs/free_space3d.h"

namespace acdplan::envs {
namespace {

constexpr const char* kFormat = "acdplan.free_space_decomposition3d/3";

// FNV-1a over the inputs' bytes, twice with different offsets: a 128-bit content key.
class ContentHash {
 public:
  void Add(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
      a_ = (a_ ^ bytes[i]) * 0x100000001b3ULL;
      b_ = (b_ ^ bytes[i]) * 0x100000001b3ULL;
    }
  }
  void Add(double x) { Add(&x, sizeof x); }
  void Add(std::int64_t x) { Add(&x, sizeof x); }
  void Add(const std::string& s) {
    Add(static_cast<std::int64_t>(s.size()));
    Add(s.data(), s.size());
  }
  std::string Hex() const {
    char text[40];
    std::snprintf(text, sizeof text, "%016" PRIx64 "%016" PRIx64, a_, b_);
    return text;
  }

 private:
  std::uint64_t a_ = 0xcbf29ce484222325ULL, b_ = 0x84222325cbf29ce4ULL;
};

std::string CacheKey(const Workspace3d& workspace, double tau) {
  ContentHash hash;
  hash.Add(std::string(kFormat));
  for (int k = 0; k < 3; ++k) hash.Add(workspace.bounds.min()[k]);
  for (int k = 0; k < 3; ++k) hash.Add(workspace.bounds.max()[k]);
  hash.Add(tau);
  hash.Add(static_cast<std::int64_t>(workspace.obstacles.size()));
  for (const acd::TriangleMesh& mesh : workspace.obstacles) {
    hash.Add(static_cast<std::int64_t>(mesh.vertices.rows()));
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
      for (int k = 0; k < 3; ++k) hash.Add(mesh.vertices(i, k));
    }
    hash.Add(static_cast<std::int64_t>(mesh.triangles.rows()));
    for (Eigen::Index i = 0; i < mesh.triangles.rows(); ++i) {
      for (int k = 0; k < 3; ++k) hash.Add(static_cast<std::int64_t>(mesh.triangles(i, k)));
    }
  }
  return hash.Hex();
}

Eigen::Matrix<double, Eigen::Dynamic, 4> HullPlanes(const acd::TriangleMesh& hull) {
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes(hull.triangles.rows(), 4);
  Eigen::Index rows = 0;
  for (Eigen::Index f = 0; f < hull.triangles.rows(); ++f) {
    const Eigen::Vector3d a = hull.vertices.row(hull.triangles(f, 0));
    const Eigen::Vector3d b = hull.vertices.row(hull.triangles(f, 1));
    const Eigen::Vector3d c = hull.vertices.row(hull.triangles(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0)) continue;
    const Eigen::Vector3d unit = n.normalized();
    planes.row(rows++) << unit.x(), unit.y(), unit.z(), unit.dot(a);
  }
  planes.conservativeResize(rows, 4);
  return planes;
}

// The area centroid of an opening's region, its holes subtracted: fan triangles of every ring,
// with their areas signed about the normal (holes run clockwise).
Eigen::Vector3d RegionCentroid(const acd::Opening3d& opening) {
  const Eigen::Vector3d n = opening.normal.normalized();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0;
  auto add = [&](const std::vector<Eigen::Vector3d>& ring) {
    for (size_t i = 1; i + 1 < ring.size(); ++i) {
      const double area = 0.5 * n.dot((ring[i] - ring[0]).cross(ring[i + 1] - ring[0]));
      sum += area * (ring[0] + ring[i] + ring[i + 1]) / 3.0;
      total += area;
    }
  };
  add(opening.polygon);
  for (const std::vector<Eigen::Vector3d>& hole : opening.holes) add(hole);
  if (total > 0) return sum / total;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : opening.polygon) mean += p;
  return opening.polygon.empty()
             ? mean
             : Eigen::Vector3d(mean / static_cast<double>(opening.polygon.size()));
}

// An orthonormal basis (u, v) of the planes of unit normal n, with u x v = n.
struct PlaneBasis {
  explicit PlaneBasis(const Eigen::Vector3d& normal) : n(normal.normalized()) {
    const Eigen::Vector3d helper =
        std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    u = n.cross(helper).normalized();
    v = n.cross(u);
    // n x u = v, so u x v = n: counter-clockwise in (u, v) is counter-clockwise seen from n.
  }
  Eigen::Vector2d In(const Eigen::Vector3d& p) const { return {p.dot(u), p.dot(v)}; }
  Eigen::Vector3d n, u, v;
};

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The convex hull of coplanar `points` in their plane (unit normal `normal`), counter-clockwise
// seen from the normal's tip.
std::vector<Eigen::Vector3d> PlanarHull(const std::vector<Eigen::Vector3d>& points,
                                        const Eigen::Vector3d& normal) {
  const PlaneBasis basis(normal);
  std::vector<Eigen::Vector2d> flat;
  double offset = 0;
  for (const Eigen::Vector3d& p : points) {
    flat.push_back(basis.In(p));
    offset += p.dot(basis.n);
  }
  offset /= static_cast<double>(std::max<size_t>(points.size(), 1));
  std::vector<Eigen::Vector3d> hull;
  for (const Eigen::Vector2d& q : acd::ConvexHull(flat)) {
    hull.push_back(q.x() * basis.u + q.y() * basis.v + offset * basis.n);
  }
  return hull;
}

// ---- The cache file: one token per number, doubles in C99 hex notation (exact). ----

std::string Hex(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}

std::string Serialise(const FreeSpaceDecomposition3d& d) {
  std::ostringstream out;
  out << kFormat << "\nkey " << d.key << "\nbounds";
  for (int k = 0; k < 3; ++k) out << ' ' << Hex(d.bounds.min()[k]);
  for (int k = 0; k < 3; ++k) out << ' ' << Hex(d.bounds.max()[k]);
  out << "\ntau " << Hex(d.tau) << "\nfree_volume " << Hex(d.free_volume) << "\ncompute_ms "
      << Hex(d.compute_ms) << "\nnotes " << d.notes.size() << '\n';
  for (const std::string& note : d.notes) out << note << '\n';
  out << "components " << d.components.size() << '\n';
  for (const FreeComponent3d& c : d.components) {
    for (int k = 0; k < 3; ++k) out << Hex(c.centroid[k]) << ' ';
    out << Hex(c.volume) << ' ' << c.hull.vertices.rows();
    for (Eigen::Index i = 0; i < c.hull.vertices.rows(); ++i) {
      for (int k = 0; k < 3; ++k) out << ' ' << Hex(c.hull.vertices(i, k));
    }
    out << ' ' << c.hull.triangles.rows();
    for (Eigen::Index i = 0; i < c.hull.triangles.rows(); ++i) {
      for (int k = 0; k < 3; ++k) out << ' ' << c.hull.triangles(i, k);
    }
    out << '\n';
  }
  out << "openings " << d.openings.size() << '\n';
  for (const FreeOpening3d& o : d.openings) {
    out << o.polygon.size();
    for (const Eigen::Vector3d& p : o.polygon) {
      for (int k = 0; k < 3; ++k) out << ' ' << Hex(p[k]);
    }
    for (int k = 0; k < 3; ++k) out << ' ' << Hex(o.centroid[k]);
    for (int k = 0; k < 3; ++k) out << ' ' << Hex(o.normal[k]);
    out << ' ' << Hex(o.area) << ' ' << Hex(o.width) << ' ' << o.component_a << ' ' << o.component_b
        << '\n';
  }
  out << "end\n";
  return out.str();
}

// Reads the tokens of a cache file; every failure is a std::runtime_error saying what broke.
class CacheReader {
 public:
  explicit CacheReader(const std::string& text) : in_(text) {}
  std::string Line() {
    std::string line;
    if (!std::getline(in_, line)) throw std::runtime_error("truncated");
    return line;
  }
  std::string Word() {
    std::string word;
    if (!(in_ >> word)) throw std::runtime_error("truncated");
    return word;
  }
  void Expect(const std::string& word) {
    const std::string got = Word();
    if (got != word) throw std::runtime_error("expected '" + word + "', got '" + got + "'");
  }
  double Real() {
    const std::string word = Word();
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size() || !std::isfinite(x)) {
      throw std::runtime_error("bad number '" + word + "'");
    }
    return x;
  }
  long Integer(long low, long high) {
    const std::string word = Word();
    char* end = nullptr;
    const long x = std::strtol(word.c_str(), &end, 10);
    if (end != word.c_str() + word.size() || x < low || x > high) {
      throw std::runtime_error("bad count '" + word + "'");
    }
    return x;
  }
  void SkipNewline() { in_.ignore(1, '\n'); }

 private:
  std::istringstream in_;
};

FreeSpaceDecomposition3d Parse(const std::string& text, const std::string& key) {
  CacheReader in(text);
  FreeSpaceDecomposition3d d;
  if (in.Line() != kFormat) throw std::runtime_error("not a " + std::string(kFormat) + " file");
  in.Expect("key");
  d.key = in.Word();
  if (d.key != key) throw std::runtime_error("its key " + d.key + " is not its name's");
  in.Expect("bounds");
  Eigen::Vector3d low, high;
  for (int k = 0; k < 3; ++k) low[k] = in.Real();
  for (int k = 0; k < 3; ++k) high[k] = in.Real();
  d.bounds = Eigen::AlignedBox3d(low, high);
  in.Expect("tau");
  d.tau = in.Real();
  in.Expect("free_volume");
  d.free_volume = in.Real();
  in.Expect("compute_ms");
  d.compute_ms = in.Real();
  in.Expect("notes");
  const long notes = in.Integer(0, 1 << 20);
  in.SkipNewline();
  for (long i = 0; i < notes; ++i) d.notes.push_back(in.Line());
  in.Expect("components");
  const long components = in.Integer(0, 1 << 24);
  for (long c = 0; c < components; ++c) {
    FreeComponent3d component;
    for (int k = 0; k < 3; ++k) component.centroid[k] = in.Real();
    component.volume = in.Real();
    const long vertices = in.Integer(0, 1 << 24);
    component.hull.vertices.resize(vertices, 3);
    for (long i = 0; i < vertices; ++i) {
      for (int k = 0; k < 3; ++k) component.hull.vertices(i, k) = in.Real();
    }
    const long triangles = in.Integer(0, 1 << 24);
    component.hull.triangles.resize(triangles, 3);
    for (long i = 0; i < triangles; ++i) {
      for (int k = 0; k < 3; ++k) {
        component.hull.triangles(i, k) = static_cast<int>(in.Integer(0, vertices - 1));
      }
    }
    component.planes = HullPlanes(component.hull);
    d.components.push_back(std::move(component));
  }
  in.Expect("openings");
  const long openings = in.Integer(0, 1 << 24);
  for (long o = 0; o < openings; ++o) {
    FreeOpening3d opening;
    const long points = in.Integer(0, 1 << 20);
    for (long i = 0; i < points; ++i) {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) p[k] = in.Real();
      opening.polygon.push_back(p);
    }
    for (int k = 0; k < 3; ++k) opening.centroid[k] = in.Real();
    for (int k = 0; k < 3; ++k) opening.normal[k] = in.Real();
    opening.area = in.Real();
    opening.width = in.Real();
    opening.component_a = static_cast<int>(in.Integer(0, components - 1));
    opening.component_b = static_cast<int>(in.Integer(0, components - 1));
    d.openings.push_back(std::move(opening));
  }
  in.Expect("end");
  return d;
}

FreeSpaceDecomposition3d Compute(const Workspace3d& workspace, double tau) {
  FreeSpaceDecomposition3d d;
  d.bounds = workspace.bounds;
  d.tau = tau;
  const FreeSpace3dResult free = FreeSpace3d(workspace);
  d.notes = free.notes;
  d.free_volume = free.volume;
  if (free.mesh.triangles.rows() == 0) return d;
  acd::PreparedMesh prepared = acd::PrepareMesh(free.mesh, {}, "free space");
  if (!prepared.solid()) {
    // Rounding the exact result to doubles can make nearly touching faces cross.
    acd::PrepareMeshOptions repair;
    repair.repair = true;
    prepared = acd::PrepareMesh(free.mesh, repair, "free space");
  }
  acd::Decomposition3d acd;
  if (prepared.solid()) {
    acd::Decompose3dOptions options;
    options.tau = tau;
    acd = acd::Decompose3d(prepared, options);
  } else {
    d.notes.push_back("free space: not a solid after rounding (" + prepared.defects.first +
                      "): one component per part, its hull");
    acd::Decompose3dOptions options;
    options.tau = 1e6 * (workspace.bounds.sizes().norm() + 1.0);  // One patch per part.
    options.surface = true;
    acd = acd::Decompose3d(prepared, options);
  }
  for (const acd::Component3d& c : acd.components) {
    FreeComponent3d component;
    component.centroid = c.centroid;
    component.volume = c.volume;
    component.hull = c.hull;
    component.planes = HullPlanes(c.hull);
    d.components.push_back(std::move(component));
  }
  // The solid ACD leaves a cut face as several regions when a later cut split it: pieces
  // between the same two components in the same plane are one passage, so they become one
  // opening -- area and centroid summed over the pieces, polygon and width those of the convex
  // hull of their outlines (a region with holes or a non-convex outline gets its hull too).
  const double tolerance = 1e-9 * (workspace.bounds.sizes().norm() + 1.0);
  std::vector<std::vector<const acd::Opening3d*>> groups;
  for (const acd::Opening3d& o : acd.openings) {
    if (o.polygon.size() < 3 || !(o.area > 0)) continue;
    const Eigen::Vector3d n = o.normal.normalized();
    bool placed = false;
    for (std::vector<const acd::Opening3d*>& group : groups) {
      const acd::Opening3d& g = *group.front();
      const Eigen::Vector3d gn = g.normal.normalized();
      if (g.component_a == o.component_a && g.component_b == o.component_b &&
          gn.dot(n) > 1 - 1e-9 && std::abs(gn.dot(o.polygon[0] - g.polygon[0])) <= tolerance) {
        group.push_back(&o);
        placed = true;
        break;
      }
    }
    if (!placed) groups.push_back({&o});
  }
  for (const std::vector<const acd::Opening3d*>& group : groups) {
    const acd::Opening3d& first = *group.front();
    FreeOpening3d opening;
    opening.normal = first.normal.normalized();
    opening.component_a = first.component_a;
    opening.component_b = first.component_b;
    std::vector<Eigen::Vector3d> points;
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
    for (const acd::Opening3d* piece : group) {
      opening.area += piece->area;
      weighted += piece->area * RegionCentroid(*piece);
      points.insert(points.end(), piece->polygon.begin(), piece->polygon.end());
    }
    opening.centroid = weighted / opening.area;
    opening.polygon = PlanarHull(points, opening.normal);
    opening.width = NarrowestWidth(opening.polygon, opening.normal);
    d.openings.push_back(std::move(opening));
  }
  return d;
}

}  // namespace

int FreeSpaceDecomposition3d::Locate(const Eigen::Vector3d& point) const {
  int best = -1;
  double best_depth = 0;
  const Eigen::Vector4d p(point.x(), point.y(), point.z(), -1.0);
  for (size_t c = 0; c < components.size(); ++c) {
    const auto& planes = components[c].planes;
    if (planes.rows() == 0) continue;
    const double depth = -(planes * p).maxCoeff();  // d - n . x for the nearest face.
    if (depth >= 0 && (best < 0 || depth > best_depth)) {
      best = static_cast<int>(c);
      best_depth = depth;
    }
  }
  return best;
}

std::vector<std::vector<int>> ComponentGraph(const FreeSpaceDecomposition3d& decomposition) {
  std::vector<std::vector<int>> graph(decomposition.components.size());
  for (const FreeOpening3d& o : decomposition.openings) {
    graph[static_cast<size_t>(o.component_a)].push_back(o.component_b);
    graph[static_cast<size_t>(o.component_b)].push_back(o.component_a);
  }
  for (std::vector<int>& list : graph) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return graph;
}

double NarrowestWidth(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& normal) {
  if (polygon.size() < 3) return 0.0;
  const PlaneBasis basis(normal);
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector3d& p : polygon) points.push_back(basis.In(p));
  const std::vector<Eigen::Vector2d> hull = acd::ConvexHull(points);
  const size_t h = hull.size();
  if (h < 3) return 0.0;
  // Rotating calipers: for each hull edge the farthest vertex (the antipodal pointer only
  // moves forward), the width in that edge's normal direction; the minimum over edges.
  double best = std::numeric_limits<double>::infinity();
  size_t j = 1;
  for (size_t i = 0; i < h; ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % h];
    const double length = (b - a).norm();
    if (!(length > 0)) continue;
    while (Cross(a, b, hull[(j + 1) % h]) > Cross(a, b, hull[j])) j = (j + 1) % h;
    best = std::min(best, Cross(a, b, hull[j]) / length);
  }
  return std::isfinite(best) ? best : 0.0;
}

std::string FreeSpaceCacheDir() {
  if (const char* dir = std::getenv("ACDPLAN_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    return std::string(xdg) + "/acdplan";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::string(home) + "/.cache/acdplan";
  }
  return "";
}

FreeSpaceDecomposition3d DecomposeFreeSpace3d(const Workspace3d& workspace,
                                              const FreeSpaceDecomposition3dOptions& options) {
  if (!(options.tau >= 0)) {
    throw InputError("DecomposeFreeSpace3d(): tau: expected a number >= 0, got " +
                     std::to_string(options.tau));
  }
  const Stopwatch stopwatch;
  const std::string key = CacheKey(workspace, options.tau);
  const std::string dir = options.cache_dir.empty() ? FreeSpaceCacheDir() : options.cache_dir;
  const std::string file =
      options.use_cache && !dir.empty() ? dir + "/free3d-" + key + ".txt" : std::string();
  std::error_code no_file;  // (A cache folder the system cannot look into has no cache.)
  if (!file.empty() && std::filesystem::exists(file, no_file)) {
    try {
      FreeSpaceDecomposition3d cached = Parse(ReadFile(file), key);
      cached.from_cache = true;
      cached.time_ms = stopwatch.Milliseconds();
      return cached;
    } catch (const std::exception& error) {
      std::cerr << "warning: " << file << ": unusable cache entry (" << error.what()
                << "); decomposing again\n";
    }
  }
  FreeSpaceDecomposition3d d = Compute(workspace, options.tau);
  d.key = key;
  d.compute_ms = stopwatch.Milliseconds();
  if (!file.empty()) {
    try {
      WriteFileAtomically(file, Serialise(d));
    } catch (const std::exception& error) {
      std::cerr << "warning: cannot write the decomposition cache: " << error.what() << "\n";
    }
  }
  d.time_ms = stopwatch.Milliseconds();
  return d;
}

}  // namespace acdplan::envs
