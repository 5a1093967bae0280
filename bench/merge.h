#pragma once
// Joining the raw records of a sharded benchmark's output folders.

#include <string>
#include <vector>

#include "bench/record.h"

namespace acdplan::bench {

/// Joins the raw records of shard folders: the manifests must agree on name, seed, runs and
/// cases; a run (case, run index) may appear in one folder only. The targets are the first
/// folder's.
/// @throws InputError "<dir>/bench.json: ..." / "<dir>/runs.csv: run 3 of case 12 is
///         also in <other dir>" otherwise.
void MergeBenchRecords(const std::vector<std::string>& dirs, BenchManifest* manifest,
                       std::vector<BenchRecord>* records);

}  // namespace acdplan::bench
