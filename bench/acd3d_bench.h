#pragma once
// The 3D ACD benchmark (tools/acd3d_bench.md): our Decompose3d() at several tau_rel against
// V-HACD v4.1 (the peer, run in the same process when the build has its header) on a set of
// meshes; every (mesh, method, tau_rel) cell runs in a child process of its own, so that its
// peak memory is its own and a crash or a hang is a row of the table, not the end of the run.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "acd/decompose3d.h"
#include "bench/targets.h"

namespace acdplan::bench {

/// Our methods and the peer, as named in the table and in targets.
inline constexpr const char* kAcdSolid = "acd-solid";      ///< Solid ACD (Ch. V.B-C).
inline constexpr const char* kAcdSurface = "acd-surface";  ///< Surface ACD (Ch. V.B).
inline constexpr const char* kVhacd = "vhacd";             ///< V-HACD v4.1, defaults, 1 thread.

/// Options for RunAcd3dBench(); `{}` is valid (every .obj under data/meshes/vhacd, relative to
/// the working directory).
struct Acd3dBenchOptions {
  std::vector<std::string> files;  ///< Empty: every .obj file of `data_dir`, sorted by name.
  std::vector<double> tau_rels;    ///< Empty: {0.2, 0.05, 0.02}; tau = tau_rel x ReferenceRadius.
  /// Empty: all of acd-solid, acd-surface, vhacd. acd-solid runs on meshes that are solid as
  /// they are or after PrepareMesh's repair; acd-surface on the others.
  std::vector<std::string> methods;
  bool surface_on_solids = false;  ///< Also run acd-surface on meshes that are solid.
  int repeats = 3;                 ///< Timed runs per cell (median); >= 1.
  double cell_budget_ms = 10000;   ///< Stop repeating a cell once its runs took this long.
  double cell_timeout_s = 120;     ///< A cell's child process is killed after this long [s].
  std::string data_dir = "data/meshes/vhacd";
  bool check = false;  ///< Run CheckDecomposition3d on our decompositions (untimed).
  /// Decompose3dOptions::feature_grouping for the solid ACD (the global cut's plane among the
  /// candidates), for before / after comparisons.
  bool feature_grouping = false;
  /// Decompose3dOptions::merge_growth for the solid ACD (unset: its default; < 0: no merge pass).
  std::optional<double> merge_growth;
  /// > 0: one more solid ACD cell on every mesh that gets the solid ACD (solid as read or after
  /// repair), at
  /// `capped_tau_rel` with Decompose3dOptions::max_hulls = this: a fine tau whose components
  /// are then merged down to V-HACD's cap, so that one setting can be tight and small. 0: none.
  int max_hulls = 64;
  double capped_tau_rel = 0.05;  ///< tau_rel of the capped cell; > 0.
};

/// One line of the table (and one object of the JSON list).
struct Acd3dBenchRow {
  std::string mesh;   ///< As shown (relative to the data folder when inside it).
  int vertices = 0;   ///< Of the prepared mesh (before repair).
  int triangles = 0;  ///< Of the prepared mesh (before repair).
  /// What PrepareMesh() found: "solid" (closed, one part), "solid-parts" (closed, several
  /// parts), "repairable" (a solid after repair), "non-solid" (not even after repair).
  std::string input;
  std::string method;                   ///< kAcdSolid, kAcdSurface or kVhacd.
  std::optional<double> tau_rel, tau;   ///< Ours only.
  int max_hulls = 0;                    ///< Ours: Decompose3dOptions::max_hulls; 0: no cap.
  std::string mode;                     ///< What ran: "solid", "solid (repaired)", "surface",
                                        ///< "voxels" (V-HACD).
  std::optional<int> parts;             ///< Empty when the cell failed or did not apply.
  std::optional<double> mesh_volume;    ///< Of the solid decomposed (repaired when repaired);
                                        ///< empty when there is no solid.
  double hull_volume = 0.0;             ///< Sum of the parts' hull volumes (acd::MeshVolume).
  std::optional<double> max_concavity;  ///< Ours only [units].
  double prepare_ms = 0.0;              ///< PrepareMesh(), with repair when it ran.
  double median_ms = 0.0;               ///< Decompose3d() / V-HACD's Compute + hulls.
  int runs = 0;
  double peak_rss_mib = 0.0;  ///< Of the cell's child process.
  std::string note;           ///< "failed: ..." (then parts is empty), "n/a (...)".
  std::string check;          ///< With `check` on our rows: "ok" or "FAIL (k)".
  /// hull_volume / mesh_volume, when both exist.
  std::optional<double> VolumeRatio() const;
  bool failed() const { return note.rfind("failed", 0) == 0; }
};

/// What RunAcd3dBench() measured.
struct Acd3dBenchResult {
  std::vector<Acd3dBenchRow> rows;
  std::vector<std::string> problems;    ///< Failed cells and failed checks, one line each.
  bool ok = true;                       ///< No cell of ours failed or failed its check.
  bool vhacd = false;                   ///< V-HACD ran (HaveVhacd() and asked for).
  double base_rss_mib = 0.0;            ///< The parent's peak RSS when the runs began.
  std::string load_before, load_after;  ///< /proc/loadavg around the runs.
};

/// Runs the benchmark; a line per cell goes to `progress` when not null.
/// @throws InputError if a file does not load, a method is unknown, or an option is out of
///         range (before any cell runs).
Acd3dBenchResult RunAcd3dBench(const Acd3dBenchOptions& options, std::ostream* progress = nullptr);

/// The report: the table, the problems, `targets` checked on the rows (no such section without
/// targets) and the machine's load.
std::string Acd3dBenchMarkdown(const Acd3dBenchResult& result, const Acd3dBenchOptions& options,
                               const std::vector<Target>& targets = {});

/// The rows as a JSON list.
std::string Acd3dBenchJson(const Acd3dBenchResult& result, const Acd3dBenchOptions& options);

/// What acd3d_bench targets can use. Labels: mesh, file (its file name), input, method, mode,
/// tau_rel and max_hulls (ours only; "0" without a cap). Metrics: parts, volume_ratio,
/// max_concavity (ours), median_ms, prepare_ms, total_s (prepare + one decomposition),
/// peak_rss_mib, failed (0 or 1; the others are NaN on a failed cell), runs, and on our rows
/// vhacd.parts, vhacd.volume_ratio, vhacd.median_ms of the same mesh where V-HACD ran.
const TargetVocabulary& Acd3dBenchTargetVocabulary();

/// The rows as target rows (labels and metrics above).
std::vector<TargetRow> Acd3dBenchTargetRows(const std::vector<Acd3dBenchRow>& rows);

}  // namespace acdplan::bench
