#include "planning/registry.h"

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

#include <array>
#include <stdexcept>

#include "base/enum_names.h"
#include "base/input_error.h"
#include "planning/acd_lead_sampler.h"
#include "planning/acd_prm.h"
#include "planning/install_acd_samplers.h"

namespace acdplan::planning {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using SamplerAllocator = ob::ValidStateSamplerAllocator;
using PlannerFactory = std::shared_ptr<ob::Planner> (*)(const ob::SpaceInformationPtr& si,
                                                        const acd::Decomposition2d* decomposition,
                                                        std::uint64_t seed);

template <typename Sampler>
SamplerAllocator Allocator() {
  return [](const ob::SpaceInformation* si) { return std::make_shared<Sampler>(si); };
}

template <typename Planner>
std::shared_ptr<ob::Planner> Make(const ob::SpaceInformationPtr& si, const acd::Decomposition2d*,
                                  std::uint64_t) {
  return std::make_shared<Planner>(si);
}

std::shared_ptr<ob::Planner> MakeAcdPrm(const ob::SpaceInformationPtr& si,
                                        const acd::Decomposition2d* decomposition,
                                        std::uint64_t seed) {
  if (!decomposition) throw std::invalid_argument("MakePlanner(): PRM_ACD needs a decomposition");
  return std::make_shared<AcdPrm>(si, *decomposition, /*star=*/false, seed);
}

struct SamplerEntry {
  SamplerType type;
  const char* name;
  SamplerAllocator (*allocator)();  ///< OMPL's sampler; null for kAcd, kAcdLead.
};

struct PlannerEntry {
  PlannerType type;
  const char* name;
  bool sample_budget;  ///< Honours the Figure-4 sample budget.
  PlannerFactory make;
};

const std::array<SamplerEntry, 7> kSamplers = {{
    {SamplerType::kUniform, "uniform", &Allocator<ob::UniformValidStateSampler>},
    {SamplerType::kGaussian, "gaussian", &Allocator<ob::GaussianValidStateSampler>},
    {SamplerType::kBridge, "bridge", &Allocator<ob::BridgeTestValidStateSampler>},
    {SamplerType::kObstacleBased, "obstacle_based", &Allocator<ob::ObstacleBasedValidStateSampler>},
    {SamplerType::kMaxClearance, "max_clearance",
     &Allocator<ob::MaximizeClearanceValidStateSampler>},
    {SamplerType::kAcd, "acd", nullptr},
    {SamplerType::kAcdLead, "acd_lead", nullptr},
}};

const std::array<PlannerEntry, 11> kPlanners = {{
    {PlannerType::kPrm, "PRM", true, &Make<og::PRM>},
    {PlannerType::kPrmAcd, "PRM_ACD", true, &MakeAcdPrm},
    {PlannerType::kPrmStar, "PRMstar", true, &Make<og::PRMstar>},
    {PlannerType::kLazyPrm, "LazyPRM", false, &Make<og::LazyPRM>},
    {PlannerType::kRrt, "RRT", false, &Make<og::RRT>},
    {PlannerType::kRrtConnect, "RRTConnect", false, &Make<og::RRTConnect>},
    {PlannerType::kRrtStar, "RRTstar", false, &Make<og::RRTstar>},
    {PlannerType::kEst, "EST", false, &Make<og::EST>},
    {PlannerType::kKpiece1, "KPIECE1", false, &Make<og::KPIECE1>},
    {PlannerType::kBkpiece1, "BKPIECE1", false, &Make<og::BKPIECE1>},
    {PlannerType::kSbl, "SBL", false, &Make<og::SBL>},
}};

/// The (value, name) view of a table, for base/enum_names.h.
template <typename Enum, typename Entry, std::size_t N>
std::array<EnumName<Enum>, N> Names(const std::array<Entry, N>& table) {
  std::array<EnumName<Enum>, N> names{};
  for (std::size_t i = 0; i < N; ++i) names[i] = {table[i].type, table[i].name};
  return names;
}

const std::array<EnumName<SamplerType>, 7> kSamplerNames = Names<SamplerType>(kSamplers);
const std::array<EnumName<PlannerType>, 11> kPlannerNames = Names<PlannerType>(kPlanners);

const PlannerEntry& Entry(PlannerType planner) {
  for (const PlannerEntry& entry : kPlanners) {
    if (entry.type == planner) return entry;
  }
  throw std::invalid_argument("planning registry: a planner without a table entry");
}

}  // namespace

std::string ToString(SamplerType sampler) { return NameOf(kSamplerNames, sampler); }
std::string ToString(PlannerType planner) { return NameOf(kPlannerNames, planner); }

SamplerType ParseSamplerType(const std::string& name) {
  return ValueOf(kSamplerNames, name, "sampler");
}

PlannerType ParsePlannerType(const std::string& name) {
  return ValueOf(kPlannerNames, name, "planner");
}

std::vector<std::string> SamplerNames() { return NamesOf(kSamplerNames); }
std::vector<std::string> PlannerNames() { return NamesOf(kPlannerNames); }

bool UsesDecomposition(SamplerType sampler) {
  return sampler == SamplerType::kAcd || sampler == SamplerType::kAcdLead;
}

bool HonoursSampleBudget(PlannerType planner) { return Entry(planner).sample_budget; }

void InstallSampler(SamplerType sampler, const std::shared_ptr<ob::SpaceInformation>& si,
                    const acd::Decomposition2d& decomposition, const AcdSamplerOptions& options,
                    const AcdLeadQuery* lead) {
  if (sampler == SamplerType::kAcd) {
    InstallAcdSamplers(si, decomposition, options);
    return;
  }
  if (sampler == SamplerType::kAcdLead) {
    if (!lead) throw std::invalid_argument("InstallSampler(): acd_lead needs the query");
    InstallAcdLeadSamplers(si, decomposition, *lead, options);
    return;
  }
  for (const SamplerEntry& entry : kSamplers) {
    if (entry.type != sampler) continue;
    InstallSeededUniformSampler(si, options.seed);
    si->setValidStateSamplerAllocator(entry.allocator());
    return;
  }
  throw std::invalid_argument("InstallSampler(): a sampler without a table entry");
}

std::shared_ptr<ob::Planner> MakePlanner(PlannerType planner,
                                         const std::shared_ptr<ob::SpaceInformation>& si,
                                         const acd::Decomposition2d* decomposition,
                                         std::uint64_t seed) {
  return Entry(planner).make(si, decomposition, seed);
}

}  // namespace acdplan::planning
