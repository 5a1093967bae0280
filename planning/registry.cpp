#include "planning/registry.h"

#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/samplers/BridgeTestValidStateSampler.h>
#include <ompl/base/samplers/GaussianValidStateSampler.h>
#include <ompl/base/samplers/MaximizeClearanceValidStateSampler.h>
#include <ompl/base/samplers/ObstacleBasedValidStateSampler.h>
#include <ompl/base/samplers/UniformValidStateSampler.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/sbl/SBL.h>

#include "acd/input_error.h"
#include "planning/acd_prm.h"
#include "planning/install_acd_samplers.h"

namespace acdplan::planning {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

std::string Joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

template <typename Sampler>
ob::ValidStateSamplerAllocator Allocator() {
  return [](const ob::SpaceInformation* si) { return std::make_shared<Sampler>(si); };
}

}  // namespace

std::vector<std::string> SamplerNames() {
  return {"uniform", "gaussian", "bridge", "obstacle_based", "max_clearance", "acd"};
}

std::vector<std::string> PlannerNames() {
  return {"PRM", "PRM_ACD", "PRMstar", "LazyPRM", "RRT", "RRTConnect", "RRTstar", "EST", "KPIECE1",
          "BKPIECE1", "SBL"};
}

bool SupportsSampleBudget(const std::string& planner) {
  return planner == "PRM" || planner == "PRM_ACD" || planner == "PRMstar";
}

void InstallSampler(const std::string& name, const std::shared_ptr<ob::SpaceInformation>& si,
                    const acd::Decomposition2d& decomposition,
                    const AcdSamplerOptions& options) {
  if (name == "acd") {
    InstallAcdSamplers(si, decomposition, options);
    return;
  }
  static const std::map<std::string, ob::ValidStateSamplerAllocator> kOmpl = {
      {"uniform", Allocator<ob::UniformValidStateSampler>()},
      {"gaussian", Allocator<ob::GaussianValidStateSampler>()},
      {"bridge", Allocator<ob::BridgeTestValidStateSampler>()},
      {"obstacle_based", Allocator<ob::ObstacleBasedValidStateSampler>()},
      {"max_clearance", Allocator<ob::MaximizeClearanceValidStateSampler>()},
  };
  const auto it = kOmpl.find(name);
  if (it == kOmpl.end()) {
    throw acd::InputError("unknown sampler '" + name + "' (known: " + Joined(SamplerNames()) +
                          ")");
  }
  InstallSeededUniformSampler(si, options.seed);
  si->setValidStateSamplerAllocator(it->second);
}

std::shared_ptr<ob::Planner> MakePlanner(const std::string& name,
                                         const std::shared_ptr<ob::SpaceInformation>& si,
                                         const acd::Decomposition2d* decomposition,
                                         std::uint64_t seed) {
  if (name == "PRM") return std::make_shared<og::PRM>(si);
  if (name == "PRM_ACD") {
    if (!decomposition) throw std::invalid_argument("MakePlanner(): PRM_ACD needs a decomposition");
    return std::make_shared<AcdPrm>(si, *decomposition, /*star=*/false, seed);
  }
  if (name == "PRMstar") return std::make_shared<og::PRMstar>(si);
  if (name == "LazyPRM") return std::make_shared<og::LazyPRM>(si);
  if (name == "RRT") return std::make_shared<og::RRT>(si);
  if (name == "RRTConnect") return std::make_shared<og::RRTConnect>(si);
  if (name == "RRTstar") return std::make_shared<og::RRTstar>(si);
  if (name == "EST") return std::make_shared<og::EST>(si);
  if (name == "KPIECE1") return std::make_shared<og::KPIECE1>(si);
  if (name == "BKPIECE1") return std::make_shared<og::BKPIECE1>(si);
  if (name == "SBL") return std::make_shared<og::SBL>(si);
  throw acd::InputError("unknown planner '" + name + "' (known: " + Joined(PlannerNames()) +
                        ")");
}

}  // namespace acdplan::planning
