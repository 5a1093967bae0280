#pragma once
// The raw record of a benchmark: one row per run (runs.csv) and the manifest (bench.json) of
// an output folder. Every other output is regenerated from these two, so a merge of shards
// and an unsharded run give the same files (apart from the measured times).

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "bench/targets.h"

namespace acdplan::bench {

/// What one case of a benchmark is: the fields every run, summary and report of the case
/// repeats. Serialised in one place (CaseCsvColumns() and the functions below it).
struct CaseDescription {
  std::string world;             ///< World name (unique in the benchmark).
  std::string family;            ///< The sweep the world belongs to (its name if none).
  double passage_width = 0.0;    ///< [units]; 0 if unknown.
  double workspace_width = 0.0;  ///< [units]
  std::string robot, sampler, planner;
  std::string budget;       ///< "200 samples" or "2 s".
  double time_limit = 0.0;  ///< [s]; 0 for a sample budget.
  int sample_budget = 0;    ///< 0 for a time budget.
};

/// The runs.csv columns of a CaseDescription, in order ("world" ... "sample_budget").
const std::vector<std::string>& CaseCsvColumns();

/// The CaseCsvColumns() fields of `c`, comma-separated (no leading or trailing comma). Reals
/// with 17 significant digits.
std::string CaseCsvFields(const CaseDescription& c);

/// Reads the CaseCsvColumns() fields starting at `fields[first]`.
/// @throws std::invalid_argument with `*column` set to the index (into `fields`) of the field
///         that cannot be read.
CaseDescription ReadCaseCsvFields(const std::vector<std::string>& fields, size_t first,
                                  size_t* column);

/// Adds the case's results.json keys (world, family, passage_width, workspace_width, robot,
/// sampler, planner, budget) to the JSON object `*object`.
void AddCaseJson(const CaseDescription& c, nlohmann::json* object);

/// How a run ended.
enum class RunStatus {
  kSolved,    ///< "solved": a solution within the budget.
  kUnsolved,  ///< "unsolved": the budget ran out.
  kCrashed,   ///< "crashed": the run died; its message is lost.
  kTimeout,   ///< "timeout": killed by the watchdog at 10 x the time limit + 60 s.
};

/// "solved", "unsolved", "crashed", "timeout".
std::string ToString(RunStatus status);

/// Inverse of ToString(). @throws InputError for any other text.
RunStatus ParseRunStatus(const std::string& text);

/// One finished run, self-describing (a merge needs no BENCH.yaml).
struct BenchRecord {
  int case_index = 0;      ///< Position of the case in the benchmark's global order.
  CaseDescription what;    ///< The case.
  int run = 0;             ///< 0-based run index within the case.
  std::uint64_t seed = 0;  ///< The run's seed (samplers and OMPL).
  RunStatus status = RunStatus::kUnsolved;
  bool solved = false;
  double time_s = 0.0;           ///< Wall time of the run [s]; acd: decomposition included.
  double decomposition_s = 0.0;  ///< Free space + ACD [s]; acd runs only (0 otherwise).
  std::uint64_t samples = 0;     ///< Samples placed / roadmap or tree vertices.
  std::uint64_t collision_checks = 0;
  double path_length = 0.0;          ///< 0 without a solution.
  int components = 0, openings = 0;  ///< Of the world's ACD.
};

/// The header line of runs.csv (no newline).
std::string BenchCsvHeader();

/// runs.csv: the header and one line per record, in the given order. Reals are written with
/// 17 significant digits so a read gives back the same numbers.
std::string BenchRecordsToCsv(const std::vector<BenchRecord>& records);

/// Reads runs.csv. @throws InputError "<path>:<line>: <rule>" for a wrong header, a
/// wrong column count or an unparsable field.
std::vector<BenchRecord> ReadBenchRecordsCsv(const std::string& path);

/// Sorts by (case_index, run) -- the global order.
void SortBenchRecords(std::vector<BenchRecord>* records);

/// What an output folder holds (bench.json).
struct BenchManifest {
  std::string name, description;
  std::string spec;                 ///< The BENCH.yaml it came from.
  std::uint64_t seed = 1;           ///< Base seed.
  int runs = 0;                     ///< Runs per case.
  int cases = 0;                    ///< Cases in the whole benchmark.
  std::vector<std::string> shards;  ///< "I/N" of each part in this folder ("1/1" unsharded).
  std::uint64_t planned_runs = 0;   ///< Runs the parts in this folder were to do.
  bool interrupted = false;         ///< A part stopped early (Ctrl-C).
  std::string hostname;             ///< Machine(s), comma-separated after a merge.
  int cpus = 0;                     ///< std::thread::hardware_concurrency() (max over parts).
  double load_average = 0.0;        ///< 1-minute load average when the (first) part started.
  int jobs = 1;                     ///< Runs in parallel.
  std::string started;              ///< "YYYY-MM-DD HH:MM:SS" UTC of the (earliest) start.
  double wall_s = 0.0;              ///< Wall time (sum over parts) [s].
  std::vector<Target> targets;      ///< The benchmark file's (bench.json: only if any).
};

std::string BenchManifestToJson(const BenchManifest& manifest);
/// @throws InputError "<path>: <key>: <rule>" for a missing or malformed field (a missing
///         "targets" is none).
BenchManifest ReadBenchManifest(const std::string& path);

}  // namespace acdplan::bench
