#include "bench/summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "base/format.h"
#include "base/input_error.h"
#include "base/json_number.h"
#include "planning/control/plan_car.h"
#include "planning/registry.h"

namespace acdplan::bench {

namespace {

std::string Fixed(double x, int digits) { return std::isnan(x) ? "—" : FormatFixed(x, digits); }

/// Seconds with 3 significant digits ("0.0123", "1.25", "12.3").
std::string Time(double s) { return std::isnan(s) ? "—" : FormatSignificant(s, 3); }

std::string Percent(double rate) { return Fixed(100.0 * rate, 0) + "%"; }

std::string Ratio(double numerator, double denominator) {
  if (std::isnan(numerator) || std::isnan(denominator)) return "—";
  if (denominator <= 0) return numerator > 0 ? "∞" : "—";
  return FormatFixed(numerator / denominator, 1) + "x";
}

/// Cases of one world, robot, planner and budget: the samplers compared with each other.
struct Group {
  CaseDescription what;  ///< The first case's (its sampler is not the group's).
  std::map<std::string, const BenchCaseSummary*> by_sampler;
  const BenchCaseSummary* Get(const std::string& sampler) const {
    auto it = by_sampler.find(sampler);
    return it == by_sampler.end() ? nullptr : it->second;
  }
  /// The sampler other than acd (and acd_lead) with the best result: highest success rate, then
  /// lowest median time to solve.
  const BenchCaseSummary* BestOther() const {
    const BenchCaseSummary* best = nullptr;
    for (const auto& [name, c] : by_sampler) {
      if (name == "acd" || name == "acd_lead") continue;
      auto better = [](const BenchCaseSummary* a, const BenchCaseSummary* b) {
        if (a->success_rate != b->success_rate) return a->success_rate > b->success_rate;
        const double ta = std::isnan(a->median_time_s) ? INFINITY : a->median_time_s;
        const double tb = std::isnan(b->median_time_s) ? INFINITY : b->median_time_s;
        return ta < tb;
      };
      if (!best || better(c, best)) best = c;
    }
    return best;
  }
  /// The sampler other than acd (and acd_lead) that solves fastest (lowest median time to solve).
  const BenchCaseSummary* FastestOther() const {
    const BenchCaseSummary* best = nullptr;
    for (const auto& [name, c] : by_sampler) {
      if (name == "acd" || name == "acd_lead" || std::isnan(c->median_time_s)) continue;
      if (!best || c->median_time_s < best->median_time_s) best = c;
    }
    return best;
  }
};

std::vector<Group> Groups(const std::vector<BenchCaseSummary>& cases) {
  std::vector<Group> groups;
  std::map<std::tuple<std::string, std::string, std::string, std::string>, size_t> index;
  for (const BenchCaseSummary& c : cases) {
    const CaseDescription& w = c.what;
    const auto key = std::make_tuple(w.world, w.robot, w.planner, w.budget);
    auto it = index.find(key);
    if (it == index.end()) {
      it = index.emplace(key, groups.size()).first;
      Group g;
      g.what = w;
      groups.push_back(g);
    }
    groups[it->second].by_sampler[w.sampler] = &c;
  }
  return groups;
}

std::string Shards(const BenchManifest& m) {
  std::string text;
  for (const std::string& s : m.shards) text += (text.empty() ? "" : ", ") + s;
  return text;
}

}  // namespace

const std::vector<std::string>& CaseStatisticNames() {
  static const std::vector<std::string> names = {"runs",
                                                 "successes",
                                                 "success_rate",
                                                 "success_ci95_lo",
                                                 "success_ci95_hi",
                                                 "median_time_s",
                                                 "p90_time_s",
                                                 "median_collision_checks",
                                                 "median_decomposition_s"};
  return names;
}

namespace {

/// `c`'s statistics as metrics "<prefix><statistic>".
void AddStatistics(const std::string& prefix, const BenchCaseSummary& c,
                   std::map<std::string, double>* metrics) {
  const double values[] = {static_cast<double>(c.runs),
                           static_cast<double>(c.successes),
                           c.success_rate,
                           c.success_ci95.first,
                           c.success_ci95.second,
                           c.median_time_s,
                           c.p90_time_s,
                           c.median_collision_checks,
                           c.median_decomposition_s};
  const std::vector<std::string>& names = CaseStatisticNames();
  for (size_t i = 0; i < names.size(); ++i) (*metrics)[prefix + names[i]] = values[i];
}

std::string CheckPlanningMetric(const std::string& metric) {
  if (metric == "samplers") return "";
  const std::string rule =
      "expected samplers or [planner/]sampler.statistic (sampler: a sampler name, best_other or "
      "fastest_other; statistic: " +
      JoinNames(CaseStatisticNames()) + "), got '" + metric + "'";
  const size_t dot = metric.rfind('.');
  if (dot == std::string::npos) return rule;
  const std::string statistic = metric.substr(dot + 1);
  std::string sampler = metric.substr(0, dot);
  const std::vector<std::string>& statistics = CaseStatisticNames();
  if (std::find(statistics.begin(), statistics.end(), statistic) == statistics.end()) return rule;
  const size_t slash = sampler.find('/');
  if (slash != std::string::npos) {
    const std::string planner = sampler.substr(0, slash);
    std::vector<std::string> planners = planning::PlannerNames();
    for (const std::string& name : planning::control::ControlPlannerNames()) {
      if (std::find(planners.begin(), planners.end(), name) == planners.end()) {
        planners.push_back(name);
      }
    }
    if (std::find(planners.begin(), planners.end(), planner) == planners.end()) {
      return "unknown planner '" + planner + "' in '" + metric +
             "' (expected one of: " + JoinNames(planners) + ")";
    }
    sampler = sampler.substr(slash + 1);
  }
  std::vector<std::string> samplers = planning::SamplerNames();
  samplers.push_back("best_other");
  samplers.push_back("fastest_other");
  // A car's cases: Syclop's decomposition in the sampler's place (bench/spec.h).
  samplers.push_back("none");
  const bool grid = sampler.size() > 4 && sampler.rfind("grid", 0) == 0 &&
                    sampler.find_first_not_of("0123456789", 4) == std::string::npos;
  if (!grid && std::find(samplers.begin(), samplers.end(), sampler) == samplers.end()) {
    return "unknown sampler '" + sampler + "' in '" + metric +
           "' (expected one of: " + JoinNames(samplers) + ")";
  }
  return "";
}

}  // namespace

const TargetVocabulary& PlanningTargetVocabulary() {
  static const TargetVocabulary vocabulary{
      {"world", "family", "robot", "planner", "budget", "budget_type"}, &CheckPlanningMetric};
  return vocabulary;
}

std::vector<TargetRow> PlanningTargetRows(const std::vector<BenchCaseSummary>& cases) {
  const std::vector<Group> groups = Groups(cases);
  std::vector<TargetRow> rows;
  for (const Group& g : groups) {
    TargetRow row;
    row.labels["world"] = g.what.world;
    row.labels["family"] = g.what.family;
    row.labels["robot"] = g.what.robot;
    row.labels["planner"] = g.what.planner;
    row.labels["budget"] = g.what.budget;
    row.labels["budget_type"] = g.what.sample_budget > 0 ? "samples" : "time";
    row.metrics["samplers"] = static_cast<double>(g.by_sampler.size());
    for (const auto& [sampler, c] : g.by_sampler) AddStatistics(sampler + ".", *c, &row.metrics);
    if (const BenchCaseSummary* best = g.BestOther()) {
      AddStatistics("best_other.", *best, &row.metrics);
    }
    if (const BenchCaseSummary* fastest = g.FastestOther()) {
      AddStatistics("fastest_other.", *fastest, &row.metrics);
    }
    // Every planner's cases on the same world, robot and budget, as "<planner>/<sampler>.".
    for (const Group& other : groups) {
      if (other.what.world != g.what.world || other.what.robot != g.what.robot ||
          other.what.budget != g.what.budget) {
        continue;
      }
      for (const auto& [sampler, c] : other.by_sampler) {
        AddStatistics(other.what.planner + "/" + sampler + ".", *c, &row.metrics);
      }
    }
    rows.push_back(row);
  }
  return rows;
}

std::string BenchResultsJson(const BenchManifest& manifest,
                             const std::vector<BenchCaseSummary>& cases) {
  nlohmann::json j;
  j["format"] = "acdplan.bench-results/1";
  j["bench"] = manifest.name;
  j["description"] = manifest.description;
  j["seed"] = manifest.seed;
  j["runs_per_case"] = manifest.runs;
  j["cases"] = nlohmann::json::array();
  for (const BenchCaseSummary& c : cases) {
    nlohmann::json e;
    e["case"] = c.case_index;
    AddCaseJson(c.what, &e);
    e["runs"] = c.runs;
    e["successes"] = c.successes;
    e["success_rate"] = c.success_rate;
    e["success_ci95"] = {c.success_ci95.first, c.success_ci95.second};
    e["median_time_s"] = JsonNumber(c.median_time_s);
    e["p90_time_s"] = JsonNumber(c.p90_time_s);
    e["median_collision_checks"] = JsonNumber(c.median_collision_checks);
    e["median_decomposition_s"] = JsonNumber(c.median_decomposition_s);
    j["cases"].push_back(e);
  }
  return j.dump(2) + "\n";
}

std::string BenchSummaryMarkdown(const BenchManifest& m,
                                 const std::vector<BenchCaseSummary>& cases) {
  std::ostringstream md;
  md << "# Benchmark `" << m.name << "`\n\n";
  if (!m.description.empty()) md << m.description << "\n\n";
  std::uint64_t done = 0;
  for (const BenchCaseSummary& c : cases) done += static_cast<std::uint64_t>(c.runs);
  md << "- spec: `" << m.spec << "`, base seed " << m.seed << ", " << m.runs << " runs per case, "
     << m.cases << " cases\n";
  md << "- runs finished: " << done << " of " << m.planned_runs << " planned (shards " << Shards(m)
     << ")" << (m.interrupted ? " — **interrupted (Ctrl-C)**" : "") << "\n";
  md << "- machine: " << m.hostname << ", " << m.cpus << " CPUs, load average "
     << Fixed(m.load_average, 2) << " at the start, " << m.jobs << " run(s) in parallel\n";
  md << "- started " << m.started << " UTC, wall time " << Fixed(m.wall_s, 1) << " s ("
     << Fixed(m.wall_s / 60.0, 1) << " min)\n\n";
  md << "Success: runs that connected start and goal within the budget, with the 95% Wilson "
        "score interval. Times are times to solve over the solved runs, in seconds. A map is "
        "decomposed once (free space + ACD, before the runs; planning/decomposition_cache.h): "
        "the times of acd and acd_lead include looking its decomposition up, and its one-off "
        "cost is the ACD [ms] column (add it for a single cold query). "
        "Checks: state validity checks.\n\n";

  std::vector<std::string> worlds;
  for (const BenchCaseSummary& c : cases) {
    const std::string& w = c.what.world;
    if (std::find(worlds.begin(), worlds.end(), w) == worlds.end()) worlds.push_back(w);
  }
  for (const std::string& world : worlds) {
    md << "## " << world << "\n\n";
    md << "| robot | sampler | planner | budget | success | 95% CI | median t | p90 t | "
          "median checks | ACD [ms] |\n";
    md << "|---|---|---|---|---:|---|---:|---:|---:|---:|\n";
    for (const BenchCaseSummary& c : cases) {
      if (c.what.world != world) continue;
      md << "| " << c.what.robot << " | " << c.what.sampler << " | " << c.what.planner << " | "
         << c.what.budget << " | " << c.successes << "/" << c.runs << " ("
         << Percent(c.success_rate) << ") | [" << Percent(c.success_ci95.first) << ", "
         << Percent(c.success_ci95.second) << "] | " << Time(c.median_time_s) << " | "
         << Time(c.p90_time_s) << " | " << Fixed(c.median_collision_checks, 0) << " | "
         << (c.what.sampler == "acd" || c.what.sampler == "acd_lead"
                 ? Fixed(1e3 * c.median_decomposition_s, 1)
                 : "—")
         << " |\n";
    }
    md << "\n";
  }

  const std::vector<Group> groups = Groups(cases);
  md << "## acd against uniform and the best other sampler\n\n";
  md << "Best other: the highest success rate among the samplers other than acd (ties: the "
        "fastest). Time ratios: their median time to solve / acd's (> 1: acd faster).\n\n";
  md << "| world | robot | planner | budget | acd | uniform | best other | success acd/uniform "
        "| time uniform/acd | time best/acd |\n";
  md << "|---|---|---|---|---:|---:|---|---:|---:|---:|\n";
  for (const Group& g : groups) {
    const BenchCaseSummary* acd = g.Get("acd");
    const BenchCaseSummary* uniform = g.Get("uniform");
    const BenchCaseSummary* best = g.BestOther();
    if (!acd || !best) continue;
    md << "| " << g.what.world << " | " << g.what.robot << " | " << g.what.planner << " | "
       << g.what.budget << " | " << Percent(acd->success_rate) << " | "
       << (uniform ? Percent(uniform->success_rate) : "—") << " | " << best->what.sampler << " "
       << Percent(best->success_rate) << " | "
       << (uniform ? Ratio(acd->success_rate, uniform->success_rate) : "—") << " | "
       << (uniform ? Ratio(uniform->median_time_s, acd->median_time_s) : "—") << " | "
       << Ratio(best->median_time_s, acd->median_time_s) << " |\n";
  }
  md << "\n";

  // The lead (acd_lead, planning/acd_lead_sampler.h) beside acd and uniform, where it ran.
  bool any_lead = false;
  for (const Group& g : groups) any_lead = any_lead || g.Get("acd_lead") != nullptr;
  if (any_lead) {
    md << "## acd_lead against acd and uniform\n\n";
    md << "Success rates on the same world, robot, planner and budget; time ratios: their "
          "median time to solve / acd_lead's (> 1: acd_lead faster).\n\n";
    md << "| world | robot | planner | budget | acd_lead | acd | uniform | time uniform/acd_lead "
          "| time acd/acd_lead |\n";
    md << "|---|---|---|---|---:|---:|---:|---:|---:|\n";
    for (const Group& g : groups) {
      const BenchCaseSummary* lead = g.Get("acd_lead");
      if (!lead) continue;
      const BenchCaseSummary* acd = g.Get("acd");
      const BenchCaseSummary* uniform = g.Get("uniform");
      md << "| " << g.what.world << " | " << g.what.robot << " | " << g.what.planner << " | "
         << g.what.budget << " | " << Percent(lead->success_rate) << " | "
         << (acd ? Percent(acd->success_rate) : "—") << " | "
         << (uniform ? Percent(uniform->success_rate) : "—") << " | "
         << (uniform ? Ratio(uniform->median_time_s, lead->median_time_s) : "—") << " | "
         << (acd ? Ratio(acd->median_time_s, lead->median_time_s) : "—") << " |\n";
    }
    md << "\n";
  }

  if (!m.targets.empty()) {
    md << "## Targets\n\n";
    md << "The benchmark file's targets (`targets:`), checked on this run's data. A row is one "
          "world, robot, planner and budget; a metric is `[planner/]sampler.statistic` of its "
          "cases (the planner defaults to the row's, so `PRM/uniform.success_rate` on a PRM_ACD "
          "row is uniform PRM's on the same world, robot and budget).\n\n";
    const std::vector<TargetRow> rows = PlanningTargetRows(cases);
    md << TargetChecksMarkdown(CheckTargets(m.targets, rows),
                               {"world", "robot", "planner", "budget"});
  }
  return md.str();
}

}  // namespace acdplan::bench
