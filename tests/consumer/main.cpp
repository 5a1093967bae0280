// A downstream OMPL program built against the installed acdplan (find_package(acdplan)): the
// README's five-line example puts the ACD sampler into OMPL's PRM on a wall with a narrow gap,
// and PRM must connect the two sides.
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRM.h>

#include <cstdio>
#include <memory>

#include "acd/decompose2d.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/install_acd_samplers.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

// Even-odd crossing test: the consumer's own validity checker (any checker works).
bool Inside(const acdplan::acd::Ring2d& ring, double x, double y) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const auto& a = ring[i];
    const auto& b = ring[j];
    if ((a.y() > y) != (b.y() > y) && x < a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside;
}

int main() {
  acdplan::envs::WallGapOptions wall;
  wall.passage_width = 0.1;
  const acdplan::envs::Workspace2d world = acdplan::envs::MakeWallWithGap(7, wall);

  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int i = 0; i < 2; ++i) {
    bounds.setLow(i, world.bounds.min()[i]);
    bounds.setHigh(i, world.bounds.max()[i]);
  }
  space->setBounds(bounds);
  og::SimpleSetup setup(space);
  setup.setStateValidityChecker([&world](const ob::State* state) {
    const auto* q = state->as<ob::RealVectorStateSpace::StateType>();
    for (const acdplan::acd::Polygon2d& obstacle : world.obstacles) {
      if (Inside(obstacle.outer, q->values[0], q->values[1])) return false;
    }
    return true;
  });
  ob::ScopedState<> start(space), goal(space);
  start[0] = 1.0, start[1] = 5.0, goal[0] = 9.0, goal[1] = 5.0;
  setup.setStartAndGoalStates(start, goal);

  // The README's example.
  auto free_space = acdplan::envs::FreeSpace2d(world);
  auto acd = acdplan::acd::Decompose2d(free_space, {/*tau=*/0.2});
  acdplan::planning::AcdSamplerOptions options;
  options.seed = 42;
  acdplan::planning::InstallAcdSamplers(setup.getSpaceInformation(), acd, options);
  setup.setPlanner(std::make_shared<og::PRM>(setup.getSpaceInformation()));

  // Until solved; the time cap only keeps a broken build from hanging.
  setup.setup();
  const ob::PlannerTerminationCondition until = ob::plannerOrTerminationCondition(
      ob::exactSolnPlannerTerminationCondition(setup.getProblemDefinition()),
      ob::timedPlannerTerminationCondition(60.0));
  if (setup.solve(until) != ob::PlannerStatus::EXACT_SOLUTION) {
    std::fprintf(stderr, "acdplan_consumer: PRM with the ACD sampler found no path\n");
    return 1;
  }
  std::printf("acdplan_consumer: %zu components; path of %zu states through the gap, ok\n",
              acd.components.size(), setup.getSolutionPath().getStateCount());
  return 0;
}
