#include "planning/internal/scenario_setup.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <stdexcept>

#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::planning::internal {

namespace ob = ompl::base;

std::string BudgetLabel(const Scenario& scenario) {
  return scenario.samples > 0 ? std::to_string(scenario.samples) + " samples"
                              : FormatSignificant(scenario.time_limit, 6) + " s";
}

CheckedSpace MakeCheckedSpace(const Eigen::VectorXd& low, const Eigen::VectorXd& high, bool rigid,
                              CountingValidityChecker::Predicate valid) {
  const int d = static_cast<int>(low.size());
  if ((d != 2 && d != 3) || high.size() != low.size()) {
    throw std::invalid_argument("MakeCheckedSpace(): expected 2 or 3 bounds on each side");
  }
  ob::RealVectorBounds bounds(static_cast<unsigned int>(d));
  for (int i = 0; i < d; ++i) {
    bounds.setLow(static_cast<unsigned int>(i), low[i]);
    bounds.setHigh(static_cast<unsigned int>(i), high[i]);
  }
  ob::StateSpacePtr space;
  if (rigid && d == 2) {
    auto s = std::make_shared<ob::SE2StateSpace>();
    s->setBounds(bounds);
    space = s;
  } else if (rigid) {
    auto s = std::make_shared<ob::SE3StateSpace>();
    s->setBounds(bounds);
    space = s;
  } else {
    auto s = std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned int>(d));
    s->setBounds(bounds);
    space = s;
  }
  CheckedSpace result;
  result.si = std::make_shared<ob::SpaceInformation>(space);
  result.checker = std::make_shared<CountingValidityChecker>(result.si.get(), std::move(valid));
  result.si->setStateValidityChecker(result.checker);
  result.si->setStateValidityCheckingResolution(0.002);
  result.si->setup();
  return result;
}

void CheckEndpoints(const CheckedSpace& space, const ob::State* start, const ob::State* goal,
                    const std::string& where) {
  if (!space.si->satisfiesBounds(start) || !space.si->isValid(start)) {
    throw InputError(where + ": start: the robot is in collision or out of bounds there");
  }
  if (!space.si->satisfiesBounds(goal) || !space.si->isValid(goal)) {
    throw InputError(where + ": goal: the robot is in collision or out of bounds there");
  }
  space.checker->ResetChecks();
}

void RunSampleBudget(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                     const ompl::base::State* start, const ompl::base::State* goal,
                     const SampleBudgetOptions& options, PlanResult* result) {
  SampleBudgetRoadmap roadmap = BuildSampleBudgetRoadmap(si, start, goal, options);
  result->solved = roadmap.solved;
  result->samples = static_cast<std::uint64_t>(roadmap.samples);
  result->path = std::move(roadmap.path);
  result->path_length = roadmap.path_length;
  result->vertices = std::move(roadmap.vertices);
  result->edges = std::move(roadmap.edges);
}

}  // namespace acdplan::planning::internal
