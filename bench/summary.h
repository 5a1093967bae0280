#pragma once
// The summaries of a planning benchmark: results.json and summary.md, with the benchmark's
// targets (bench/targets.h) checked on them.

#include <string>
#include <vector>

#include "bench/record.h"
#include "bench/stats.h"
#include "bench/targets.h"

namespace acdplan::bench {

/// results.json: {"format": "acdplan.bench-results/1", "bench": ..., "cases": [{world, robot,
/// sampler, planner, budget, runs, successes, success_rate, success_ci95: [lo, hi],
/// median_time_s, p90_time_s, median_collision_checks, ...}]} (times null without a success).
std::string BenchResultsJson(const BenchManifest& manifest,
                             const std::vector<BenchCaseSummary>& cases);

/// summary.md: the machine and wall time, a table per world, and per world (and robot,
/// planner, budget) acd against uniform and against the best other sampler, then the
/// manifest's targets checked one by one (no such section without targets).
std::string BenchSummaryMarkdown(const BenchManifest& manifest,
                                 const std::vector<BenchCaseSummary>& cases);

/// The statistics of a case a target can name: runs, successes, success_rate,
/// success_ci95_lo, success_ci95_hi, median_time_s, p90_time_s, median_collision_checks,
/// median_decomposition_s.
const std::vector<std::string>& CaseStatisticNames();

/// What targets of a planning benchmark can use. Labels: world, family, robot, planner,
/// budget, budget_type ("time" or "samples"). Metrics: "samplers" (how many samplers the row
/// has) and "[planner/]sampler.statistic", where sampler is a sampler name, "best_other" (the
/// highest success rate other than acd, ties: the fastest) or "fastest_other" (the lowest
/// median time to solve other than acd), and planner (default: the row's) another planner's
/// case on the same world, robot and budget.
const TargetVocabulary& PlanningTargetVocabulary();

/// One target row per world x robot x planner x budget, with the metrics above.
std::vector<TargetRow> PlanningTargetRows(const std::vector<BenchCaseSummary>& cases);

}  // namespace acdplan::bench
