#pragma once
// The files of a benchmark's output folder, all regenerated from its raw record (runs.csv and
// bench.json): results.json, summary.md, one OMPL benchmark log per world. (Plots are the
// command line's: tools/plot_bench.py reads the folder.)

#include <string>
#include <vector>

#include "bench/record.h"

namespace acdplan::bench {

/// Writes runs.csv, bench.json, results.json, summary.md and the OMPL logs into `dir`
/// (created if needed), each atomically; `records` are sorted first. Removes the OMPL logs of
/// worlds `records` does not have (an earlier run into the same folder).
/// @throws std::runtime_error naming the path if a file cannot be written.
void WriteBenchOutputs(const std::string& dir, const BenchManifest& manifest,
                       std::vector<BenchRecord> records);

/// Writes only the raw record (runs.csv, bench.json): a cheap checkpoint.
void WriteBenchRecord(const std::string& dir, const BenchManifest& manifest,
                      std::vector<BenchRecord> records);

}  // namespace acdplan::bench
