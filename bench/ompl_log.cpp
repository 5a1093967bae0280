#include "bench/ompl_log.h"

#include <ompl/config.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "base/format.h"

namespace acdplan::bench {

namespace {

/// OMPL's version: OMPL_VERSION, or (as Debian's OMPL 1.5 package defines it as "") the
/// major.minor.patch macros.
std::string OmplVersion() {
  const std::string version = OMPL_VERSION;
  if (!version.empty()) return version;
  return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
         std::to_string(OMPL_PATCH_VERSION);
}

}  // namespace

std::string BenchOmplLogName(const std::string& world) { return "ompl_" + world + ".log"; }

std::string BenchOmplLog(const BenchManifest& m, const std::vector<BenchRecord>& records,
                         const std::string& world) {
  std::vector<const BenchRecord*> runs;
  for (const BenchRecord& r : records) {
    if (r.what.world == world) runs.push_back(&r);
  }
  double time_limit = 0.0, total = 0.0, width = 0.0, workspace = 0.0;
  std::vector<int> case_order;
  std::map<int, std::vector<const BenchRecord*>> by_case;
  for (const BenchRecord* r : runs) {
    time_limit = std::max(time_limit, r->what.time_limit);
    total += r->time_s;
    width = r->what.passage_width;
    workspace = r->what.workspace_width;
    if (!by_case.count(r->case_index)) case_order.push_back(r->case_index);
    by_case[r->case_index].push_back(r);
  }
  auto real = [](double x) { return FormatSignificant(x, 9); };
  std::ostringstream log;
  log << "OMPL version " << OmplVersion() << "\n";
  log << "Experiment " << m.name << "." << world << "\n";
  log << "3 experiment properties\n";
  log << "passage_width REAL = " << real(width) << "\n";
  log << "workspace_width REAL = " << real(workspace) << "\n";
  log << "runs_per_case INTEGER = " << m.runs << "\n";
  log << "Running on " << (m.hostname.empty() ? "unknown" : m.hostname) << "\n";
  log << "Starting at " << m.started << "\n";
  log << "<<<|\n";
  log << "acdplan bench " << m.spec << " (" << m.name << "), world " << world << "\n";
  log << "Each planner below is one robot x sampler x planner x budget; time includes the ACD\n";
  log << "decomposition for the acd sampler (also reported as decomposition time).\n";
  log << "|>>>\n";
  log << "<<<|\n" << m.cpus << " CPUs\n|>>>\n";
  log << m.seed << " is the random seed\n";
  log << real(time_limit) << " seconds per run\n";
  log << "0 MB per run\n";
  log << m.runs << " runs per planner\n";
  log << real(total) << " seconds spent to collect the data\n";
  log << "1 enum type\n";
  log << "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|"
         "Approximate solution|Exact solution|Crash|Abort|Infeasible\n";
  log << case_order.size() << " planners\n";
  for (int index : case_order) {
    const std::vector<const BenchRecord*>& rs = by_case[index];
    const CaseDescription& f = rs.front()->what;
    log << f.planner << " [" << f.sampler << "] " << f.robot << ", " << f.budget << "\n";
    log << "4 common properties\n";
    log << "planner = " << f.planner << "\n";
    log << "sampler = " << f.sampler << "\n";
    log << "robot = " << f.robot << "\n";
    log << "budget = " << f.budget << "\n";
    log << "13 properties for each run\n";
    log << "time REAL\nsolved BOOLEAN\nstatus ENUM\ngraph states INTEGER\nsolution length REAL\n"
           "collision checks INTEGER\nsamples INTEGER\ndecomposition time REAL\n"
           "components INTEGER\nopenings INTEGER\nseed INTEGER\nrun INTEGER\n"
           "approximate solution BOOLEAN\n";
    log << rs.size() << " runs\n";
    for (const BenchRecord* r : rs) {
      const bool finished = r->status == RunStatus::kSolved || r->status == RunStatus::kUnsolved;
      // OMPL's PlannerStatus: 4 timeout (budget used up), 6 exact solution, 7 crash, 8 abort.
      const int status = r->solved                           ? 6
                         : r->status == RunStatus::kUnsolved ? 4
                         : r->status == RunStatus::kCrashed  ? 7
                                                             : 8;
      log << (finished ? real(r->time_s) : "nan") << "; " << (r->solved ? 1 : 0) << "; " << status
          << "; " << r->samples << "; " << (r->solved ? real(r->path_length) : "") << "; "
          << r->collision_checks << "; " << r->samples << "; " << real(r->decomposition_s) << "; "
          << r->components << "; " << r->openings << "; " << r->seed << "; " << r->run << "; 0; \n";
    }
    log << ".\n";
  }
  return log.str();
}

}  // namespace acdplan::bench
