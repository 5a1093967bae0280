#include "planning/sample_budget_roadmap.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>

#include <map>
#include <stdexcept>

#include "planning/acd_prm.h"

namespace acdplan::planning {

namespace {

/// PRM (or PRM_ACD) with its roadmap-building steps made callable one milestone at a time.
template <typename Prm>
class Budget : public Prm {
 public:
  using Prm::addMilestone;
  using Prm::constructSolution;
  using Prm::Prm;
  using Prm::sameComponent;
};

// Places the samples into `prm` (set up on `pdef` here) and reads the roadmap back.
template <typename Prm>
SampleBudgetRoadmap BuildWith(Prm& prm, const std::shared_ptr<ompl::base::SpaceInformation>& si,
                              const std::shared_ptr<ompl::base::ProblemDefinition>& pdef,
                              const ompl::base::State* start, const ompl::base::State* goal,
                              const SampleBudgetOptions& options) {
  prm.setProblemDefinition(pdef);
  prm.setup();

  SampleBudgetRoadmap result;
  const typename Prm::Vertex vs = prm.addMilestone(si->cloneState(start));
  const typename Prm::Vertex vg = prm.addMilestone(si->cloneState(goal));
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

  const typename Prm::Graph& g = prm.getRoadmap();
  auto state_of = boost::get(typename Prm::vertex_state_t(), g);
  std::map<typename Prm::Vertex, int> index;
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
  if (options.acd_connections) {
    Budget<AcdPrm> prm(si, *options.acd_connections, options.star, options.seed);
    return BuildWith(prm, si, pdef, start, goal, options);
  }
  if (options.acd_connections_3d) {
    Budget<AcdPrm> prm(si, options.acd_connections_3d, options.star, options.seed);
    return BuildWith(prm, si, pdef, start, goal, options);
  }
  Budget<ompl::geometric::PRM> prm(si, options.star);
  return BuildWith(prm, si, pdef, start, goal, options);
}

}  // namespace acdplan::planning
