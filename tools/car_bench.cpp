// car_bench: a quick look at control-space cars: Syclop with the ACD decomposition vs OMPL's
// grid, and RRT / KPIECE1 without a decomposition. The measurement of record is
// `acdplan bench configs/bench/kinodynamic.yaml` (one process per run, seeded;
// docs/bench/kinodynamic).
//
//   car_bench WORLD.yaml CAR RUNS TIME_LIMIT [LENGTH]
//
// WORLD.yaml is a scenario (its workspace, robot, start, goal are used); CAR kinematic_car or
// dynamic_car. Runs are sequential in one process (OMPL's global seed is set once, to 1), so
// a run is not reproducible on its own, only the set; a first look, not `acdplan bench`.

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "planning/control/plan_car.h"
#include "planning/plan_scenario.h"
#include "planning/scenario.h"

using namespace acdplan::planning;
using namespace acdplan::planning::control;

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: car_bench WORLD.yaml CAR RUNS TIME_LIMIT [LENGTH]\n");
    return 2;
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(1);
  const Scenario scenario = LoadScenario(argv[1]);
  CarQuery base;
  base.workspace = scenario.workspace;
  base.robot = scenario.robot;
  base.model = ParseCarModel(argv[2]);
  const int runs = std::atoi(argv[3]);
  base.time_limit = std::atof(argv[4]);
  if (argc > 5) base.car.length = std::atof(argv[5]);
  base.start = Eigen::Vector3d(scenario.start[0], scenario.start[1], 0.0);
  base.goal = Eigen::Vector3d(scenario.goal[0], scenario.goal[1], 0.0);
  base.tau_diag = scenario.tau_diag;
  struct Config {
    ControlPlanner planner;
    DecompositionKind decomposition;
    int cells;
  };
  std::vector<Config> configs;
  for (ControlPlanner p : {ControlPlanner::kSyclopRrt, ControlPlanner::kSyclopEst}) {
    configs.push_back({p, DecompositionKind::kAcd, 0});
    for (int cells : {10, 20, 40}) configs.push_back({p, DecompositionKind::kGrid, cells});
  }
  configs.push_back({ControlPlanner::kRrt, DecompositionKind::kAcd, 0});
  configs.push_back({ControlPlanner::kKpiece1, DecompositionKind::kAcd, 0});
  std::printf(
      "| world | car | planner | decomposition | regions | solved | median t [s] | ACD [ms] |\n");
  std::printf("|---|---|---|---|---:|---:|---:|---:|\n");
  for (const Config& config : configs) {
    CarQuery q = base;
    q.planner = config.planner;
    q.decomposition = config.decomposition;
    q.grid_cells = std::max(1, config.cells);
    int solved = 0, regions = 0;
    double acd_ms = 0;
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
      const CarResult result = PlanCar(q);
      regions = result.regions;
      acd_ms = result.decomposition_ms;
      if (result.solved) {
        ++solved;
        times.push_back(result.time_s);
      }
    }
    std::sort(times.begin(), times.end());
    const double median = times.empty() ? -1 : times[times.size() / 2];
    const bool syclop = config.planner == ControlPlanner::kSyclopRrt ||
                        config.planner == ControlPlanner::kSyclopEst;
    const std::string decomposition =
        !syclop ? "—"
        : config.decomposition == DecompositionKind::kAcd
            ? "acd"
            : "grid " + std::to_string(config.cells) + "x" + std::to_string(config.cells);
    std::printf("| %s | %s | %s | %s | %d | %d/%d | %.3g | %.2f |\n", argv[1], argv[2],
                ToString(config.planner).c_str(), decomposition.c_str(), regions, solved, runs,
                median, syclop && config.decomposition == DecompositionKind::kAcd ? acd_ms : 0.0);
    std::fflush(stdout);
  }
  return 0;
}
