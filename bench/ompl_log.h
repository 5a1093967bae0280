#pragma once
// The OMPL benchmark log of a planning benchmark's world.

#include <string>
#include <vector>

#include "bench/record.h"

namespace acdplan::bench {

/// The OMPL benchmark log of `world` (the format of ompl::tools::Benchmark::saveResultsToFile,
/// which ompl_benchmark_statistics reads into SQLite): one "planner" per robot x sampler x
/// planner x budget, with the run properties time, solved, status, graph states, solution
/// length and the custom ones: collision checks, samples, decomposition time, components,
/// openings, seed. Written here rather than by ompl::tools::Benchmark, which can only run
/// its own loop in one process: this way a merge of shards writes the same log. The first line
/// names the OMPL version acdplan was built with.
std::string BenchOmplLog(const BenchManifest& manifest, const std::vector<BenchRecord>& records,
                         const std::string& world);

/// The file name of `world`'s log: "ompl_<world>.log".
std::string BenchOmplLogName(const std::string& world);

}  // namespace acdplan::bench
