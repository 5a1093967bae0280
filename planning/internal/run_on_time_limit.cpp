#include "planning/internal/run_on_time_limit.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/geometric/PathGeometric.h>

#include <memory>
#include <vector>

namespace acdplan::planning::internal {
namespace ob = ompl::base;

void RunOnTimeLimit(const ob::PlannerPtr& planner, const ob::ScopedState<>& start,
                    const ob::ScopedState<>& goal, double time_limit, PlanResult* result) {
  const ob::SpaceInformationPtr& si = planner->getSpaceInformation();
  const ob::StateSpacePtr& space = si->getStateSpace();
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal);
  planner->setProblemDefinition(pdef);
  planner->setup();
  const ob::PlannerStatus status = planner->solve(time_limit);
  result->solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  if (result->solved) {
    auto* path = pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    result->path_length = path->length();
    for (const ob::State* state : path->getStates()) {
      std::vector<double> reals;
      space->copyToReals(reals, state);
      result->path.push_back(reals);
    }
  }
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  result->samples = data.numVertices();
  for (unsigned int i = 0; i < data.numVertices(); ++i) {
    std::vector<double> reals;
    space->copyToReals(reals, data.getVertex(i).getState());
    result->vertices.push_back(reals);
    std::vector<unsigned int> out;
    data.getEdges(i, out);
    for (unsigned int j : out) result->edges.emplace_back(static_cast<int>(i), static_cast<int>(j));
  }
}

}  // namespace acdplan::planning::internal
