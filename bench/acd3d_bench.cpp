// The 3D ACD benchmark: see bench/acd3d_bench.h and tools/acd3d_bench.md.

#include "bench/acd3d_bench.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "acd/check_decomposition3d.h"
#include "acd/decompose3d.h"
#include "acd/decomposition3d.h"
#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "bench/cell_process.h"
#include "bench/time_runs.h"
#include "bench/vhacd_peer.h"
#include "envs/mesh_loader.h"

namespace acdplan::bench {

namespace {

using Json = nlohmann::ordered_json;  // Keys in the documented order.

const char* const kSolid = "solid";
const char* const kSolidParts = "solid-parts";
const char* const kRepairable = "repairable";
const char* const kNonSolid = "non-solid";

/// One mesh file and what the probe (PrepareMesh in a child process) found.
struct BenchMesh {
  std::string name;  ///< As shown.
  std::string path;
  int vertices = 0, triangles = 0;
  std::string input;  ///< kSolid, kSolidParts, kRepairable, kNonSolid ("" if the probe failed).
  std::optional<double> volume;  ///< Of the solid (repaired when kRepairable).
  double radius = 0.0;           ///< acd::ReferenceRadius of the prepared mesh.
  std::string probe_problem;     ///< Why the probe failed, or a repair that failed.
};

/// `path` relative to `data_dir` when it lies inside it, else as given.
std::string DisplayName(const std::string& path, const std::string& data_dir) {
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, ec);
  const std::filesystem::path dir = std::filesystem::weakly_canonical(data_dir, ec);
  if (ec) return path;
  const std::filesystem::path relative = file.lexically_relative(dir);
  if (relative.empty() || *relative.begin() == "..") return path;
  return relative.string();
}

std::vector<std::string> DefaultFiles(const std::string& data_dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(data_dir, ec)) {
    throw InputError("--data " + data_dir +
                     ": not a folder (the default is relative to the working directory: run from "
                     "the repository, or give --data DIR or mesh files)");
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".obj") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());  // Directory order is not reproducible.
  return files;
}

double SumOfHullVolumes(const std::vector<acd::TriangleMesh>& hulls) {
  double sum = 0.0;
  for (const acd::TriangleMesh& hull : hulls) sum += acd::MeshVolume(hull);
  return sum;
}

/// The probe's first stage, in a child: load and PrepareMesh without repair.
std::string ProbeWork(const std::string& path) {
  const acd::TriangleMesh mesh = envs::ReadMesh(path);
  const acd::PreparedMesh prepared = acd::PrepareMesh(mesh, {}, path);
  Json out = {{"vertices", prepared.mesh.vertices.rows()},
              {"triangles", prepared.mesh.triangles.rows()},
              {"solid", prepared.solid()},
              {"parts", prepared.parts.size()},
              {"radius", acd::ReferenceRadius(prepared.mesh)}};
  if (prepared.solid()) out["volume"] = acd::MeshVolume(prepared.mesh);
  return out.dump();
}

/// The probe's second stage, in a child (repair is the riskiest step: CGAL's experimental
/// self-intersection removal): PrepareMesh with repair.
std::string RepairProbeWork(const std::string& path) {
  const acd::PreparedMesh prepared =
      acd::PrepareMesh(envs::ReadMesh(path), acd::PrepareMeshOptions{true}, path);
  Json out = {{"solid", prepared.solid()}, {"first", prepared.defects.first}};
  if (prepared.solid()) out["volume"] = acd::MeshVolume(prepared.mesh);
  return out.dump();
}

BenchMesh Probe(const std::string& path, const Acd3dBenchOptions& options) {
  BenchMesh mesh;
  mesh.path = path;
  mesh.name = DisplayName(path, options.data_dir);
  const CellOutcome first = RunCellProcess([&] { return ProbeWork(path); }, options.cell_timeout_s);
  if (first.status != CellStatus::kOk) {
    mesh.probe_problem = "PrepareMesh " + first.reason;
    return mesh;
  }
  const Json probe = Json::parse(first.output);
  mesh.vertices = probe["vertices"].get<int>();
  mesh.triangles = probe["triangles"].get<int>();
  mesh.radius = probe["radius"].get<double>();
  if (probe["solid"].get<bool>()) {
    mesh.input = probe["parts"].get<int>() == 1 ? kSolid : kSolidParts;
    mesh.volume = probe["volume"].get<double>();
    return mesh;
  }
  mesh.input = kNonSolid;
  const CellOutcome second =
      RunCellProcess([&] { return RepairProbeWork(path); }, options.cell_timeout_s);
  if (second.status != CellStatus::kOk) {
    mesh.probe_problem = "PrepareMesh with repair " + second.reason;
    return mesh;
  }
  const Json repaired = Json::parse(second.output);
  if (repaired["solid"].get<bool>()) {
    mesh.input = kRepairable;
    mesh.volume = repaired["volume"].get<double>();
  }
  return mesh;
}

/// One of our cells, in a child: prepare (repairing for a repairable mesh when `solid`), then
/// time Decompose3d. Returns the row's measured fields as JSON.
std::string OursWork(const BenchMesh& mesh, bool solid, double tau, int max_hulls,
                     const Acd3dBenchOptions& options) {
  const acd::TriangleMesh input = envs::ReadMesh(mesh.path);
  const Stopwatch stopwatch;
  acd::PrepareMeshOptions prepare;
  prepare.repair = solid && mesh.input == kRepairable;
  const acd::PreparedMesh prepared = acd::PrepareMesh(input, prepare, mesh.path);
  const double prepare_ms = stopwatch.Milliseconds();
  if (solid) acd::RequireSolid(prepared, mesh.path);
  acd::Decompose3dOptions decompose;
  decompose.tau = tau;
  decompose.surface = !solid;
  decompose.feature_grouping = options.feature_grouping;
  decompose.merge_growth = options.merge_growth;
  decompose.max_hulls = max_hulls;
  auto timed = TimeRuns([&] { return acd::Decompose3d(prepared, decompose); }, options.repeats,
                        options.cell_budget_ms, 1);
  const acd::Decomposition3d& result = timed.result;
  double hull_volume = 0.0;
  for (const acd::Component3d& component : result.components) {
    hull_volume += acd::MeshVolume(component.hull);
  }
  Json out = {{"mode", result.stats.surface ? "surface"
                       : prepare.repair     ? "solid (repaired)"
                                            : "solid"},
              {"parts", result.components.size()},
              {"hull_volume", hull_volume},
              {"max_concavity", result.stats.max_concavity},
              {"prepare_ms", prepare_ms},
              {"median_ms", timed.median_ms},
              {"runs", timed.runs}};
  if (options.check) {
    const acd::DecompositionCheck check = acd::CheckDecomposition3d(prepared, result);
    out["problems"] = check.problems;
  }
  return out.dump();
}

/// The V-HACD cell, in a child: V-HACD gets the mesh as read (identical vertices joined), as
/// its users give it; the hull volumes are measured by us.
std::string VhacdWork(const BenchMesh& mesh, const Acd3dBenchOptions& options) {
  const acd::TriangleMesh input = envs::ReadMesh(mesh.path);
  auto timed =
      TimeRuns([&] { return VhacdHulls(input); }, options.repeats, options.cell_budget_ms, 1);
  Json out = {{"mode", "voxels"},
              {"parts", timed.result.size()},
              {"hull_volume", SumOfHullVolumes(timed.result)},
              {"prepare_ms", 0.0},
              {"median_ms", timed.median_ms},
              {"runs", timed.runs}};
  return out.dump();
}

Acd3dBenchRow RowFor(const BenchMesh& mesh, const std::string& method) {
  Acd3dBenchRow row;
  row.mesh = mesh.name;
  row.vertices = mesh.vertices;
  row.triangles = mesh.triangles;
  row.input = mesh.input;
  row.method = method;
  row.mesh_volume = mesh.volume;
  return row;
}

/// Runs one cell's `work` in a child and fills `row` from its answer (or its failure).
void RunCell(const std::function<std::string()>& work, const Acd3dBenchOptions& options,
             Acd3dBenchRow* row, std::vector<std::string>* problems) {
  const CellOutcome outcome = RunCellProcess(work, options.cell_timeout_s);
  row->peak_rss_mib = outcome.peak_rss_mib;
  const std::string where =
      row->mesh + ", " + row->method +
      (row->tau_rel ? ", tau_rel " + FormatSignificant(*row->tau_rel, 6) : "") +
      (row->max_hulls > 0 ? ", max_hulls " + std::to_string(row->max_hulls) : "");
  if (outcome.status != CellStatus::kOk) {
    row->note = "failed: " + outcome.reason;
    problems->push_back(where + ": " + outcome.reason);
    return;
  }
  const Json out = Json::parse(outcome.output);
  row->mode = out["mode"].get<std::string>();
  row->parts = out["parts"].get<int>();
  row->hull_volume = out["hull_volume"].get<double>();
  if (out.contains("max_concavity")) row->max_concavity = out["max_concavity"].get<double>();
  row->prepare_ms = out["prepare_ms"].get<double>();
  row->median_ms = out["median_ms"].get<double>();
  row->runs = out["runs"].get<int>();
  if (out.contains("problems")) {
    const std::vector<std::string> check = out["problems"].get<std::vector<std::string>>();
    row->check = check.empty() ? "ok" : "FAIL (" + std::to_string(check.size()) + ")";
    // The first few per cell: a broken decomposition can have a problem per component.
    constexpr size_t kShown = 3;
    for (size_t i = 0; i < check.size() && i < kShown; ++i) {
      problems->push_back(where + ": check: " + check[i]);
    }
    if (check.size() > kShown) {
      problems->push_back(where + ": check: ... and " + std::to_string(check.size() - kShown) +
                          " more");
    }
  }
}

std::string LoadAverage() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(file >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

double OwnPeakRssMib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

bool Wanted(const Acd3dBenchOptions& options, const char* method) {
  return options.methods.empty() ||
         std::find(options.methods.begin(), options.methods.end(), method) != options.methods.end();
}

void CheckOptions(const Acd3dBenchOptions& options) {
  for (const std::string& method : options.methods) {
    if (method != kAcdSolid && method != kAcdSurface && method != kVhacd) {
      throw InputError("--method " + method + ": unknown (expected one of: " + kAcdSolid + ", " +
                       kAcdSurface + ", " + kVhacd + ")");
    }
  }
  for (double tau_rel : options.tau_rels) {
    if (!(tau_rel > 0) || !std::isfinite(tau_rel)) {
      throw InputError("--tau-rel " + FormatShortest(tau_rel) + ": must be finite and > 0");
    }
  }
  if (options.repeats < 1) throw InputError("--repeats must be >= 1");
  if (!(options.cell_timeout_s > 0)) throw InputError("--cell-timeout-s must be > 0");
  if (options.max_hulls < 0) {
    throw InputError("--max-hulls " + std::to_string(options.max_hulls) +
                     ": must be >= 0 (0: no capped cell)");
  }
  if (!(options.capped_tau_rel > 0) || !std::isfinite(options.capped_tau_rel)) {
    throw InputError("--capped-tau-rel " + FormatShortest(options.capped_tau_rel) +
                     ": must be finite and > 0");
  }
  for (const std::string& file : options.files) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw InputError(file + ": no such file");
  }
}

std::string FormatMs(double ms) {
  if (ms < 10.0) return FormatFixed(ms, 2);
  if (ms < 1000.0) return FormatFixed(ms, 0);
  return FormatSignificant(ms, 4);
}

std::string MarkdownTable(const std::vector<Acd3dBenchRow>& rows, bool with_check) {
  std::ostringstream out;
  out << "| mesh | V | F | input | method | tau_rel | max hulls | mode | parts | hull vol / vol "
         "| max concavity | prepare ms | median ms | runs | peak MiB |"
      << (with_check ? " check |" : "") << "\n";
  out << "|---|---:|---:|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|"
      << (with_check ? "---|" : "") << "\n";
  std::string previous;
  for (const Acd3dBenchRow& row : rows) {
    const bool first = row.mesh != previous;  // The mesh's figures once, so groups stand out.
    previous = row.mesh;
    out << "| " << (first ? row.mesh : "") << " | " << (first ? std::to_string(row.vertices) : "")
        << " | " << (first ? std::to_string(row.triangles) : "") << " | "
        << (first ? row.input : "") << " | " << row.method << " | "
        << (row.tau_rel ? FormatSignificant(*row.tau_rel, 6) : "—") << " | "
        << (row.max_hulls > 0 ? std::to_string(row.max_hulls) : "—") << " | ";
    if (row.parts) {
      const std::optional<double> ratio = row.VolumeRatio();
      out << row.mode << " | " << *row.parts << " | " << (ratio ? FormatFixed(*ratio, 3) : "n/a")
          << " | " << (row.max_concavity ? FormatSignificant(*row.max_concavity, 3) : "—") << " | "
          << (row.method == kVhacd ? "—" : FormatMs(row.prepare_ms)) << " | "
          << FormatMs(row.median_ms) << " | " << row.runs << " | "
          << FormatFixed(row.peak_rss_mib, 0) << " |";
    } else {
      // The full reason is in the problems list below the table.
      out << " | **" << (row.failed() ? "failed" : row.note) << "** | | | | | | "
          << (row.peak_rss_mib > 0 ? FormatFixed(row.peak_rss_mib, 0) : "") << " |";
    }
    if (with_check) out << " " << row.check << " |";
    out << "\n";
  }
  return out.str();
}

template <typename T>
Json OrNull(const std::optional<T>& value) {
  return value ? Json(*value) : Json(nullptr);
}

}  // namespace

std::optional<double> Acd3dBenchRow::VolumeRatio() const {
  if (!parts || !mesh_volume || !(*mesh_volume > 0)) return std::nullopt;
  return hull_volume / *mesh_volume;
}

Acd3dBenchResult RunAcd3dBench(const Acd3dBenchOptions& options, std::ostream* progress) {
  CheckOptions(options);
  const std::vector<std::string> files =
      options.files.empty() ? DefaultFiles(options.data_dir) : options.files;
  const std::vector<double> tau_rels =
      options.tau_rels.empty() ? std::vector<double>{0.2, 0.05, 0.02} : options.tau_rels;
  Acd3dBenchResult result;
  result.vhacd = HaveVhacd() && Wanted(options, kVhacd);
  result.base_rss_mib = OwnPeakRssMib();
  result.load_before = LoadAverage();
  auto report = [&](const Acd3dBenchRow& row) {
    if (!progress) return;
    *progress << "acd3d_bench: " << row.mesh << " " << row.method;
    if (row.tau_rel) *progress << " tau_rel " << FormatSignificant(*row.tau_rel, 6);
    if (row.max_hulls > 0) *progress << " max_hulls " << row.max_hulls;
    if (row.parts) {
      *progress << ": " << *row.parts << " parts, " << FormatMs(row.median_ms) << " ms, "
                << FormatFixed(row.peak_rss_mib, 0) << " MiB";
    } else {
      *progress << ": " << row.note;
    }
    *progress << std::endl;
  };
  for (const std::string& file : files) {
    const BenchMesh mesh = Probe(file, options);
    if (progress) {
      *progress << "acd3d_bench: " << mesh.name << " (V " << mesh.vertices << ", F "
                << mesh.triangles << ", " << (mesh.input.empty() ? "probe failed" : mesh.input)
                << ")" << std::endl;
    }
    if (mesh.input.empty()) {
      Acd3dBenchRow row = RowFor(mesh, "prepare");
      row.note = "failed: " + mesh.probe_problem;
      result.problems.push_back(mesh.name + ": " + mesh.probe_problem);
      result.ok = false;
      result.rows.push_back(row);
      continue;
    }
    if (!mesh.probe_problem.empty())
      result.problems.push_back(mesh.name + ": " + mesh.probe_problem);
    const bool solid = mesh.input != kNonSolid;
    const bool surface =
        mesh.input == kNonSolid || mesh.input == kRepairable || options.surface_on_solids;
    for (const char* method : {kAcdSolid, kAcdSurface}) {
      const bool is_solid = method == std::string(kAcdSolid);
      if (!Wanted(options, method) || !(is_solid ? solid : surface)) continue;
      // (tau_rel, max_hulls): the settings, then for the solid ACD (of a mesh solid as read or
      // after repair) the capped one.
      std::vector<std::pair<double, int>> settings;
      for (double tau_rel : tau_rels) settings.emplace_back(tau_rel, 0);
      if (is_solid && options.max_hulls > 0) {
        settings.emplace_back(options.capped_tau_rel, options.max_hulls);
      }
      for (const auto& [tau_rel, max_hulls] : settings) {
        Acd3dBenchRow row = RowFor(mesh, method);
        // What should run, so that a failed cell still groups with its mesh's other settings
        // (targets' any_of); the cell reports what did run.
        row.mode = !is_solid ? "surface" : mesh.input == kRepairable ? "solid (repaired)" : "solid";
        row.tau_rel = tau_rel;
        row.tau = tau_rel * mesh.radius;
        row.max_hulls = max_hulls;
        const double tau = *row.tau;
        const int cap = max_hulls;  // C++17 lambdas cannot capture a structured binding.
        RunCell([&] { return OursWork(mesh, is_solid, tau, cap, options); }, options, &row,
                &result.problems);
        if (row.failed() || row.check.rfind("FAIL", 0) == 0) result.ok = false;
        report(row);
        result.rows.push_back(row);
      }
    }
    if (result.vhacd) {
      Acd3dBenchRow row = RowFor(mesh, kVhacd);
      row.mode = "voxels";
      RunCell([&] { return VhacdWork(mesh, options); }, options, &row, &result.problems);
      report(row);
      result.rows.push_back(row);
    }
  }
  result.load_after = LoadAverage();
  return result;
}

std::string Acd3dBenchMarkdown(const Acd3dBenchResult& result, const Acd3dBenchOptions& options,
                               const std::vector<Target>& targets) {
  std::ostringstream out;
  out << "# acd3d_bench\n\n";
  out << "Our Decompose3d() (tau = tau_rel x acd::ReferenceRadius of the prepared mesh; solid ACD "
         "on meshes that are solid, or solid after PrepareMesh's repair; surface ACD on the "
         "others"
      << (options.surface_on_solids ? " and on the solids too" : ", and on repairable ones too")
      << (options.feature_grouping ? "; solid ACD with feature grouping" : "")
      << (!options.merge_growth
              ? "; tau-convex neighbours merged while their hull grows by <= tau_rel / 2"
          : *options.merge_growth >= 0
              ? "; tau-convex neighbours merged while their hull grows by <= " +
                    FormatSignificant(*options.merge_growth, 6)
              : "; no merge pass")
      << ")";
  if (options.max_hulls > 0) {
    out << ", and the solid ACD once more at tau_rel "
        << FormatSignificant(options.capped_tau_rel, 6) << " merged down to at most "
        << options.max_hulls << " parts (max hulls: Decompose3dOptions::max_hulls)";
  }
  if (result.vhacd) {
    out << " and V-HACD v4.1 (defaults: <= 64 hulls, 400,000 voxels; synchronous, one thread) on "
           "the mesh as read";
  } else {
    out << "; V-HACD did not run ("
        << (HaveVhacd() ? "not asked for" : "built without ACDPLAN_VHACD_INCLUDE_DIR") << ")";
  }
  out << ". Each cell runs in its own child process (peak MiB: its peak resident set, wait4; the "
         "parent's own was "
      << FormatFixed(result.base_rss_mib, 0)
      << " MiB at the start, which a child starts from); killed after "
      << FormatSignificant(options.cell_timeout_s, 6)
      << " s. median ms: median wall time of Decompose3d() (or of V-HACD's Compute and its hulls) "
         "over up to "
      << options.repeats << " runs, fewer once a cell's runs took "
      << FormatSignificant(options.cell_budget_ms, 6)
      << " ms; prepare ms: PrepareMesh() once (with repair for `solid (repaired)`). hull vol / "
         "vol: sum of the parts' hull volumes (acd::MeshVolume) / volume of the solid (n/a "
         "without one). input: solid (closed, one piece), solid-parts (closed, several pieces), "
         "repairable (solid after --repair), non-solid.\n\n";
  out << MarkdownTable(result.rows, options.check) << "\n";
  const std::vector<std::string>& problems = result.problems;
  out << "Problems (failed cells" << (options.check ? ", CheckDecomposition3d failures" : "")
      << ", failed repairs): " << (problems.empty() ? "none" : std::to_string(problems.size()))
      << "\n\n";
  for (const std::string& problem : problems) out << "- " << problem << "\n";
  if (!problems.empty()) out << "\n";
  if (!targets.empty()) {
    const std::vector<TargetRow> target_rows = Acd3dBenchTargetRows(result.rows);
    out << "## Targets\n\n"
        << TargetChecksMarkdown(CheckTargets(targets, target_rows),
                                {"mesh", "input", "method", "tau_rel", "max_hulls"})
        << "\n";
  }
  out << "Machine: " << std::thread::hardware_concurrency()
      << " hardware threads (std::thread::hardware_concurrency); load average "
      << result.load_before << " before, " << result.load_after << " after the runs.\n";
  return out.str();
}

std::string Acd3dBenchJson(const Acd3dBenchResult& result, const Acd3dBenchOptions& options) {
  Json list = Json::array();
  for (const Acd3dBenchRow& row : result.rows) {
    const bool measured = row.parts.has_value();
    Json item = {{"mesh", row.mesh},
                 {"vertices", row.vertices},
                 {"triangles", row.triangles},
                 {"input", row.input},
                 {"method", row.method},
                 {"tau_rel", OrNull(row.tau_rel)},
                 {"tau", OrNull(row.tau)},
                 {"max_hulls", row.method == kVhacd ? Json(nullptr) : Json(row.max_hulls)},
                 {"mode", row.mode},
                 {"parts", OrNull(row.parts)},
                 {"mesh_volume", OrNull(row.mesh_volume)},
                 {"hull_volume", measured ? Json(row.hull_volume) : Json(nullptr)},
                 {"volume_ratio", OrNull(row.VolumeRatio())},
                 {"max_concavity", OrNull(row.max_concavity)},
                 {"prepare_ms", measured ? Json(row.prepare_ms) : Json(nullptr)},
                 {"median_ms", measured ? Json(row.median_ms) : Json(nullptr)},
                 {"runs", row.runs},
                 {"peak_rss_mib", row.peak_rss_mib}};
    if (!row.note.empty()) item["note"] = row.note;
    if (options.check && !row.check.empty()) item["check"] = row.check;
    list.push_back(std::move(item));
  }
  return list.dump(1) + "\n";
}

namespace {

const char* const kMetrics[] = {"parts",        "volume_ratio", "max_concavity",
                                "median_ms",    "prepare_ms",   "total_s",
                                "peak_rss_mib", "failed",       "runs"};
const char* const kPeerMetrics[] = {"vhacd.parts", "vhacd.volume_ratio", "vhacd.median_ms"};

std::string CheckMetric(const std::string& metric) {
  for (const char* known : kMetrics) {
    if (metric == known) return "";
  }
  for (const char* known : kPeerMetrics) {
    if (metric == known) return "";
  }
  std::string expected;
  for (const char* known : kMetrics) expected += std::string(expected.empty() ? "" : ", ") + known;
  for (const char* known : kPeerMetrics) expected += std::string(", ") + known;
  return "unknown metric '" + metric + "' (expected one of: " + expected + ")";
}

}  // namespace

const TargetVocabulary& Acd3dBenchTargetVocabulary() {
  static const TargetVocabulary vocabulary{
      {"mesh", "file", "input", "method", "mode", "tau_rel", "max_hulls"}, &CheckMetric};
  return vocabulary;
}

std::vector<TargetRow> Acd3dBenchTargetRows(const std::vector<Acd3dBenchRow>& rows) {
  const double nan = std::nan("");
  std::vector<TargetRow> out;
  for (const Acd3dBenchRow& row : rows) {
    TargetRow t;
    t.labels["mesh"] = row.mesh;
    t.labels["file"] = std::filesystem::path(row.mesh).filename().string();
    t.labels["input"] = row.input;
    t.labels["method"] = row.method;
    t.labels["mode"] = row.mode;
    if (row.tau_rel) t.labels["tau_rel"] = FormatSignificant(*row.tau_rel, 6);
    if (row.method != kVhacd) t.labels["max_hulls"] = std::to_string(row.max_hulls);
    const bool measured = row.parts.has_value();
    t.metrics["failed"] = row.failed() ? 1.0 : 0.0;
    t.metrics["parts"] = measured ? *row.parts : nan;
    // Absent (not applicable) without a solid; NaN (missed) on a failed cell.
    if (row.mesh_volume) t.metrics["volume_ratio"] = row.VolumeRatio().value_or(nan);
    if (row.method != kVhacd) t.metrics["max_concavity"] = row.max_concavity.value_or(nan);
    t.metrics["median_ms"] = measured ? row.median_ms : nan;
    t.metrics["prepare_ms"] = measured ? row.prepare_ms : nan;
    t.metrics["total_s"] = measured ? 1e-3 * (row.prepare_ms + row.median_ms) : nan;
    t.metrics["peak_rss_mib"] = row.peak_rss_mib > 0 ? row.peak_rss_mib : nan;
    t.metrics["runs"] = row.runs;
    if (row.method != kVhacd) {
      for (const Acd3dBenchRow& peer : rows) {
        if (peer.mesh != row.mesh || peer.method != kVhacd) continue;
        // A failed V-HACD cell: a comparison with it is not measured, so it misses.
        t.metrics["vhacd.parts"] = peer.parts ? *peer.parts : nan;
        if (peer.mesh_volume) t.metrics["vhacd.volume_ratio"] = peer.VolumeRatio().value_or(nan);
        t.metrics["vhacd.median_ms"] = peer.parts ? peer.median_ms : nan;
      }
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace acdplan::bench
