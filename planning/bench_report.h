#pragma once
// The outputs of a benchmark folder, all regenerated from its raw record (runs.csv and
// bench.json): results.json, summary.md, one OMPL benchmark log per world, plots.

#include <iosfwd>
#include <string>
#include <vector>

#include "planning/bench_record.h"
#include "planning/bench_stats.h"

namespace acdplan::planning {

/// results.json: {"format": "acdplan.bench-results/1", "bench": ..., "cases": [{world, robot,
/// sampler, planner, budget, runs, successes, success_rate, success_ci95: [lo, hi],
/// median_time_s, p90_time_s, median_collision_checks, ...}]} (times null without a success).
std::string BenchResultsJson(const BenchManifest& manifest,
                             const std::vector<BenchCaseSummary>& cases);

/// summary.md: the machine and wall time, a table per world, and per world (and robot,
/// planner, budget) acd against uniform and against the best other sampler, then the
/// issue's targets checked one by one.
std::string BenchSummaryMarkdown(const BenchManifest& manifest,
                                 const std::vector<BenchCaseSummary>& cases);

/// The OMPL benchmark log of `world` (the format of ompl::tools::Benchmark::saveResultsToFile,
/// which ompl_benchmark_statistics reads into SQLite): one "planner" per robot x sampler x
/// planner x budget, with the run properties time, solved, status, graph states, solution
/// length and the custom ones: collision checks, samples, decomposition time, components,
/// openings, seed. Written here rather than by ompl::tools::Benchmark, which can only run
/// its own loop in one process: this way a merge of shards writes the same log.
std::string BenchOmplLog(const BenchManifest& manifest, const std::vector<BenchRecord>& records,
                         const std::string& world);

/// The file name of `world`'s log: "ompl_<world>.log".
std::string BenchOmplLogName(const std::string& world);

/// Writes runs.csv, bench.json, results.json, summary.md and the OMPL logs into `dir`
/// (created if needed), each atomically; `records` are sorted first. Then, if `plot`, runs
/// tools/plot_bench.py (python3 with matplotlib) for the PNGs, and says on `log` what it did
/// or why it could not.
/// @throws std::runtime_error naming the path if a file cannot be written.
void WriteBenchOutputs(const std::string& dir, const BenchManifest& manifest,
                       std::vector<BenchRecord> records, bool plot, std::ostream* log);

/// Writes only the raw record (runs.csv, bench.json): a cheap checkpoint.
void WriteBenchRecord(const std::string& dir, const BenchManifest& manifest,
                      std::vector<BenchRecord> records);

/// Joins the raw records of shard folders: the manifests must agree on name, seed, runs and
/// cases; a run (case, run index) may appear in one folder only.
/// @throws InputError "<dir>/bench.json: ..." / "<dir>/runs.csv: run 3 of case 12 is
///         also in <other dir>" otherwise.
void MergeBenchRecords(const std::vector<std::string>& dirs, BenchManifest* manifest,
                       std::vector<BenchRecord>* records);

/// The plot script: $ACDPLAN_PLOT_BENCH if set, else next to the executable's share folder
/// or the source tree's tools/plot_bench.py; "" if none exists.
std::string FindPlotBenchScript();

}  // namespace acdplan::planning
