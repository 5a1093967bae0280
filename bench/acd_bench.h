#pragma once
// The 2D ACD benchmark (tools/acd_bench.md): our Decompose2d() with each concavity measure
// against CGAL's convex partitions (the peer measured in the same run, DESIGN.md) on a list of
// polygon files; a Markdown table, a JSON copy of it, and optional targets checked on the rows.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "bench/targets.h"

namespace acdplan::bench {

/// Options for RunAcdBench(); `{}` is valid (the default list under data/polygons/acd2d,
/// relative to the working directory).
struct AcdBenchOptions {
  std::vector<std::string> files;  ///< Empty: AcdBenchDefaultInputs() under `data_dir`.
  std::vector<double> tau_rels;    ///< Empty: {0.01, 0}.
  int repeats = 21;                ///< Timed runs per cell (fewer when a cell is slow); >= 1.
  double cell_budget_ms = 2000.0;  ///< Stop repeating a cell after this much time, >= 3 runs.
  int optimal_max_vertices = 150;  ///< CGAL's O(n^4) optimal partition only up to this n.
  std::string data_dir = "data/polygons/acd2d";  ///< Folder of the default list.
  bool check = false;  ///< Run CheckDecomposition on each of our decompositions.
};

/// The default inputs, relative to `AcdBenchOptions::data_dir`.
const std::vector<std::string>& AcdBenchDefaultInputs();

/// One line of the table (and one object of the JSON list).
struct AcdBenchRow {
  std::string polygon;
  int vertices = 0, notches = 0, holes = 0;
  std::optional<double> tau_rel, tau;  ///< Empty for CGAL's partitions (no tolerance).
  std::string method;                  ///< "acd-sl", ..., "cgal-approx", ...
  std::optional<int> components;       ///< Empty when the method did not run (see `note`).
  double convexity = 0.0;
  double median_ms = 0.0;
  int runs = 0;
  std::string note;   ///< "n/a (holes)", "n/a (n > 150)", "failed: ...".
  std::string check;  ///< With `check` on our rows: "ok" or "FAIL (k)".
};

/// What RunAcdBench() measured.
struct AcdBenchResult {
  std::vector<AcdBenchRow> rows;
  std::vector<std::string> skipped;     ///< Default inputs that did not load, with the reason.
  std::vector<std::string> problems;    ///< Ours that threw or failed the check; CGAL failures.
  bool ok = true;                       ///< None of ours threw or failed the check.
  std::string load_before, load_after;  ///< /proc/loadavg around the runs.
};

/// Runs the benchmark; a line per polygon goes to `progress` when not null.
/// @throws InputError if a file named in `options.files` does not load (the default
///         list skips such files instead).
AcdBenchResult RunAcdBench(const AcdBenchOptions& options, std::ostream* progress = nullptr);

/// The report: the table, the skipped files, the problems, `targets` checked on the rows (no
/// such section without targets) and the machine's load.
std::string AcdBenchMarkdown(const AcdBenchResult& result, const AcdBenchOptions& options,
                             const std::vector<Target>& targets = {});

/// The rows as a JSON list (with "check" when `options.check`).
std::string AcdBenchJson(const AcdBenchResult& result, const AcdBenchOptions& options);

/// What acd_bench targets can use. Labels: polygon (as in the table), file (its file name),
/// method, tau_rel (absent on CGAL's rows). Metrics: components, convexity, median_ms, runs
/// (NaN when our decomposition failed; absent when a CGAL method did not run), and on our rows
/// "<cgal method>.components" of the same polygon where that partition ran with a valid output.
const TargetVocabulary& AcdBenchTargetVocabulary();

/// The rows as target rows (labels and metrics above).
std::vector<TargetRow> AcdBenchTargetRows(const std::vector<AcdBenchRow>& rows);

}  // namespace acdplan::bench
