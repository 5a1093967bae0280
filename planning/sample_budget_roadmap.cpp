#include "planning/sample_budget_roadmap.h"

#include <map>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <stdexcept>

namespace acdplan::planning {

namespace {

/// PRM with its roadmap-building steps made callable one milestone at a time.
class BudgetPrm : public ompl::geometric::PRM {
 public:
  using PRM::PRM;
  using PRM::addMilestone;
  using PRM::constructSolution;
  using PRM::sameComponent;
};

}  // namespace

SampleBudgetRoadmap BuildSampleBudgetRoadmap(
    const std::shared_ptr<ompl::base::SpaceInformation>& si, const ompl::base::State* start,
    const ompl::base::State* goal, const SampleBudgetOptions& options) {
  if (options.samples < 1) {
    throw std::invalid_argument("BuildSampleBudgetRoadmap(): samples must be >= 1, got " +
                                std::to_string(options.samples));
  }
  if (!si->isSetup()) si->setup();
  if (!si->isValid(start) || !si->isValid(goal)) {
    throw std::invalid_argument("BuildSampleBudgetRoadmap(): the start or the goal is invalid");
  }
  auto pdef = std::make_shared<ompl::base::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal);
  BudgetPrm prm(si, options.star);
  prm.setProblemDefinition(pdef);
  prm.setup();

  SampleBudgetRoadmap result;
  const BudgetPrm::Vertex vs = prm.addMilestone(si->cloneState(start));
  const BudgetPrm::Vertex vg = prm.addMilestone(si->cloneState(goal));
  ompl::base::ValidStateSamplerPtr sampler = si->allocValidStateSampler();
  ompl::base::State* work = si->allocState();
  const int give_up =
      options.max_failed_calls > 0 ? options.max_failed_calls : 10 * options.samples + 100;
  int failed = 0;
  while (result.samples < options.samples && failed < give_up) {
    if (sampler->sample(work)) {
      prm.addMilestone(si->cloneState(work));
      ++result.samples;
      failed = 0;
    } else {
      ++failed;
    }
  }
  si->freeState(work);
  result.solved = prm.sameComponent(vs, vg);

  const BudgetPrm::Graph& g = prm.getRoadmap();
  auto state_of = boost::get(BudgetPrm::vertex_state_t(), g);
  std::map<BudgetPrm::Vertex, int> index;
  for (auto [it, end] = boost::vertices(g); it != end; ++it) {
    index[*it] = static_cast<int>(result.vertices.size());
    std::vector<double> reals;
    si->getStateSpace()->copyToReals(reals, state_of[*it]);
    result.vertices.push_back(reals);
  }
  for (auto [it, end] = boost::edges(g); it != end; ++it) {
    result.edges.emplace_back(index[boost::source(*it, g)], index[boost::target(*it, g)]);
  }
  if (result.solved) {
    ompl::base::PathPtr path = prm.constructSolution(vs, vg);
    if (auto* geometric = dynamic_cast<ompl::geometric::PathGeometric*>(path.get())) {
      result.path_length = geometric->length();
      for (const ompl::base::State* state : geometric->getStates()) {
        std::vector<double> reals;
        si->getStateSpace()->copyToReals(reals, state);
        result.path.push_back(reals);
      }
    }
  }
  return result;
}

}  // namespace acdplan::planning
