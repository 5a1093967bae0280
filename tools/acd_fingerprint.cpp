// acd_fingerprint: a hash of every decomposition of a polygon or mesh corpus, so a change meant
// to be a pure speed-up can show that the output stayed bit-identical (run it before and after
// and compare), and that builds with other standard libraries agree (tools/stdlib_check.sh);
// and a repeat mode that runs one 2D decomposition many times for a profiler. Not a test.
//
//   acd_fingerprint [--tau-rel R ...] [--measure M ...] FILE_OR_FOLDER...
//       One line per polygon file x measure x tau_rel: the hash of the whole Decomposition2d (its
//       JSON, whose numbers read back bit for bit, and every tree node) and the component count;
//       one line per mesh file (.obj, .off) x tau_rel: the hash of its Decomposition3d's JSON
//       (`acdplan decompose MESH`'s choices: solid ACD, or surface ACD of an open mesh; a closed
//       mesh that is no solid is repaired first) and the component count; a last line with the
//       hash of all lines. Unreadable files are listed and skipped.
//   acd_fingerprint --repeat N --measure M --tau-rel R FILE
//       Decomposes FILE N times (nothing else), for callgrind or perf.
//
// tau is tau_rel x the largest reference radius of the file, as in acd_bench (meshes: x the
// mesh's ReferenceRadius(), as `acdplan decompose` takes it).
// Exit status: 0 done; 2 bad usage.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "acd/decompose2d.h"
#include "acd/decompose3d.h"
#include "acd/decomposition3d_io.h"
#include "acd/decomposition_io.h"
#include "acd/prepare_mesh.h"
#include "acd/read_polygons.h"
#include "base/file_io.h"
#include "base/input_error.h"
#include "envs/obj_off_reader.h"

namespace {

namespace acd = acdplan::acd;

// FNV-1a over the bytes of each value, so equal hashes mean (barring collisions) equal bits.
class Hasher {
 public:
  void Add(std::uint64_t bits) {
    for (int k = 0; k < 8; ++k) {
      hash_ = (hash_ ^ ((bits >> (8 * k)) & 0xffu)) * 1099511628211ull;
    }
  }
  void Add(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    Add(bits);
  }
  void Add(int value) { Add(static_cast<std::uint64_t>(static_cast<std::int64_t>(value))); }
  void Add(const acd::Point2d& p) {
    Add(p.x());
    Add(p.y());
  }
  void Add(const acd::Ring2d& ring) {
    Add(static_cast<int>(ring.size()));
    for (const acd::Point2d& p : ring) Add(p);
  }
  void Add(const acd::Polygon2d& polygon) {
    Add(polygon.outer);
    Add(static_cast<int>(polygon.holes.size()));
    for (const acd::Ring2d& hole : polygon.holes) Add(hole);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 1469598103934665603ull;
};

// The decomposition JSON (full precision: nlohmann writes the shortest text that reads back to
// the same double) without the time, then the hierarchy tree, which the JSON leaves out.
std::uint64_t HashOf(acd::Decomposition2d d) {
  d.stats.time_ms = 0;
  Hasher h;
  for (const char c : acd::DecompositionToJson(d, {})) h.Add(static_cast<int>(c));
  h.Add(static_cast<int>(d.tree.size()));
  for (const acd::HierarchyNode2d& node : d.tree) {
    h.Add(node.piece);
    h.Add(node.concavity);
    h.Add(node.witness);
    h.Add(static_cast<int>(node.cuts.size()));
    for (const acd::Cut2d& cut : node.cuts) {
      h.Add(cut.from);
      h.Add(cut.to);
    }
    h.Add(node.parent);
    h.Add(node.children[0]);
    h.Add(node.children[1]);
    h.Add(node.component);
    h.Add(node.depth);
  }
  for (const int root : d.roots) h.Add(root);
  return h.value();
}

bool IsMesh(const std::filesystem::path& file) {
  return file.extension() == ".obj" || file.extension() == ".off";
}

std::vector<std::string> ListFiles(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    if (std::filesystem::is_directory(path)) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
        if (entry.is_regular_file() &&
            (acd::IsPolygonFile(entry.path().string()) || IsMesh(entry.path()))) {
          files.push_back(entry.path().string());
        }
      }
    } else {
      files.push_back(path);
    }
  }
  std::sort(files.begin(), files.end());  // Directory order is not portable.
  return files;
}

std::vector<acd::Polygon2d> Read(const std::string& file, double* radius) {
  std::vector<double> radii;
  std::vector<acd::Polygon2d> polygons = acd::ReadPolygons(file, &radii);
  *radius = 0.0;
  for (const double r : radii) *radius = std::max(*radius, r);
  return polygons;
}

// The line of a mesh file at one tau_rel (see the top of the file).
std::string MeshLine(const std::string& file, double tau_rel) {
  std::istringstream in(acdplan::ReadFile(file));
  const acd::TriangleMesh mesh = std::filesystem::path(file).extension() == ".off"
                                     ? acdplan::envs::ReadOff(in, file)
                                     : acdplan::envs::ReadObj(in, file);
  acd::PrepareMeshOptions prepare;
  acd::PreparedMesh prepared = acd::PrepareMesh(mesh, prepare, file);
  if (!prepared.solid() && prepared.defects.boundary_edges == 0) {  // Closed, no solid.
    prepare.repair = true;
    prepared = acd::PrepareMesh(mesh, prepare, file);
  }
  acd::Decompose3dOptions options;
  options.tau = tau_rel * acd::ReferenceRadius(prepared.mesh);
  acd::Decomposition3d d = acd::Decompose3d(prepared, options);
  d.stats.time_ms = 0;
  Hasher h;
  for (const char c : acd::Decomposition3dToJson(d, {})) h.Add(static_cast<int>(c));
  char line[512];
  std::snprintf(line, sizeof line, "%s mesh %g %016llx %zu", file.c_str(), tau_rel,
                static_cast<unsigned long long>(h.value()), d.components.size());
  return line;
}

int Run(const std::vector<std::string>& paths, const std::vector<std::string>& measures,
        const std::vector<double>& tau_rels, int repeat) {
  if (repeat > 0) {
    if (paths.size() != 1 || measures.size() != 1 || tau_rels.size() != 1) {
      throw acdplan::InputError("--repeat takes one FILE, one --measure and one --tau-rel");
    }
    double radius = 0.0;
    const std::vector<acd::Polygon2d> polygons = Read(paths[0], &radius);
    acd::Decompose2dOptions options;
    options.measure = acd::ParseConcavityMeasure(measures[0]);
    options.tau = tau_rels[0] * radius;
    std::size_t components = 0;
    for (int r = 0; r < repeat; ++r) components += Decompose2d(polygons, options).components.size();
    std::cout << components / static_cast<std::size_t>(repeat) << " components\n";
    return 0;
  }
  Hasher all;
  auto print = [&all](const std::string& line) {
    std::cout << line << "\n";
    for (const char c : line) all.Add(static_cast<int>(c));
  };
  for (const std::string& file : ListFiles(paths)) {
    if (IsMesh(file)) {
      for (const double tau_rel : tau_rels) {
        try {
          print(MeshLine(file, tau_rel));
        } catch (const std::exception& e) {
          print(file + " mesh " + std::to_string(tau_rel) + " failed: " + e.what());
        }
      }
      continue;
    }
    double radius = 0.0;
    std::vector<acd::Polygon2d> polygons;
    try {
      polygons = Read(file, &radius);
    } catch (const acdplan::InputError& e) {
      std::cout << file << " skipped: " << e.what() << "\n";
      continue;
    }
    for (const std::string& name : measures) {
      for (const double tau_rel : tau_rels) {
        acd::Decompose2dOptions options;
        options.measure = acd::ParseConcavityMeasure(name);
        options.tau = tau_rel * radius;
        options.keep_pieces = true;  // Every node's piece goes into the hash.
        char line[512];
        try {
          const acd::Decomposition2d d = Decompose2d(polygons, options);
          std::snprintf(line, sizeof line, "%s %s %g %016llx %zu", file.c_str(), name.c_str(),
                        tau_rel, static_cast<unsigned long long>(HashOf(d)), d.components.size());
        } catch (const std::exception& e) {
          std::snprintf(line, sizeof line, "%s %s %g failed: %s", file.c_str(), name.c_str(),
                        tau_rel, e.what());
        }
        print(line);
      }
    }
  }
  char total[32];
  std::snprintf(total, sizeof total, "%016llx", static_cast<unsigned long long>(all.value()));
  std::cout << "all " << total << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  std::vector<std::string> measures = {"sl", "sp", "h1", "h2"};
  std::vector<double> tau_rels = {0.0, 0.01, 0.05};
  int repeat = 0;
  CLI::App app{"acd_fingerprint: hashes of decompositions, or repeated 2D runs for a profiler"};
  app.add_option("paths", paths, "Polygon or mesh files, or folders (searched recursively)")
      ->required();
  app.add_option("--measure", measures, "sl, sp, h1, h2; repeatable")->allow_extra_args(false);
  app.add_option("--tau-rel", tau_rels, "tau relative to the reference radius; repeatable")
      ->allow_extra_args(false)
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--repeat", repeat, "Decompose one file this many times and print nothing else")
      ->check(CLI::Range(1, 1000000));
  CLI11_PARSE(app, argc, argv);
  try {
    return Run(paths, measures, tau_rels, repeat);
  } catch (const acdplan::InputError& e) {
    std::cerr << "acd_fingerprint: " << e.what() << "\n";
    return 2;
  }
}
