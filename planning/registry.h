#pragma once
// The samplers and planners acdplan can run, by enum and by name: one table of each drives
// scenario validation, the command line's help, benchmarks and the factories below.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "acd/decomposition2d.h"
#include "planning/acd_sampler_options.h"

namespace ompl::base {
class Planner;
class SpaceInformation;
}  // namespace ompl::base

namespace acdplan::planning {

struct AcdLeadQuery;

/// The valid-state samplers: OMPL's five and acdplan's ACD sampler.
enum class SamplerType {
  kUniform,        ///< "uniform": ompl::base::UniformValidStateSampler.
  kGaussian,       ///< "gaussian": GaussianValidStateSampler.
  kBridge,         ///< "bridge": BridgeTestValidStateSampler.
  kObstacleBased,  ///< "obstacle_based": ObstacleBasedValidStateSampler.
  kMaxClearance,   ///< "max_clearance": MaximizeClearanceValidStateSampler.
  kAcd,            ///< "acd": AcdValidStateSampler (planning/install_acd_samplers.h).
  kAcdLead,        ///< "acd_lead": the ACD as a lead (planning/acd_lead_sampler.h); also
                   ///< `sampler: {name: acd, lead: true}` in a scenario.
};

/// The geometric planners.
enum class PlannerType {
  kPrm,         ///< "PRM"
  kPrmAcd,      ///< "PRM_ACD": PRM connecting along the ACD (planning/acd_prm.h).
  kPrmStar,     ///< "PRMstar"
  kLazyPrm,     ///< "LazyPRM"
  kRrt,         ///< "RRT"
  kRrtConnect,  ///< "RRTConnect"
  kRrtStar,     ///< "RRTstar"
  kEst,         ///< "EST"
  kKpiece1,     ///< "KPIECE1"
  kBkpiece1,    ///< "BKPIECE1"
  kSbl,         ///< "SBL"
};

/// The name of a sampler or planner, as scenarios, the command line and reports spell it.
std::string ToString(SamplerType sampler);
std::string ToString(PlannerType planner);

/// Inverses of ToString().
/// @throws InputError "unknown sampler '<name>' (expected one of: uniform, ...)" /
///         "unknown planner '<name>' (expected one of: PRM, ...)".
SamplerType ParseSamplerType(const std::string& name);
PlannerType ParsePlannerType(const std::string& name);

/// Every sampler / planner name, in the tables' order (for help texts and sweeps).
std::vector<std::string> SamplerNames();
std::vector<std::string> PlannerNames();

/// Whether `planner` grows a roadmap that the Figure-4 sample-budget protocol can drive
/// (BuildSampleBudgetRoadmap()): PRM, PRM_ACD and PRMstar.
bool HonoursSampleBudget(PlannerType planner);

/// Installs `sampler` on `si`. kAcd: InstallAcdSamplers(si, decomposition, options).
/// kAcdLead: InstallAcdLeadSamplers(si, decomposition, *lead, options). Any other: seeded
/// uniform state sampling (InstallSeededUniformSampler(si, options.seed)) and OMPL's
/// valid-state sampler, so every sampler is reproducible from the seed.
/// @throws std::invalid_argument for kAcdLead without `lead` (the query it follows).
void InstallSampler(SamplerType sampler, const std::shared_ptr<ompl::base::SpaceInformation>& si,
                    const acd::Decomposition2d& decomposition, const AcdSamplerOptions& options,
                    const AcdLeadQuery* lead = nullptr);

/// True for the samplers that use the decomposition (acd, acd_lead): their runs count its
/// time.
bool UsesDecomposition(SamplerType sampler);

/// A new geometric planner on `si` with OMPL's default parameters. kPrmAcd connects along
/// `decomposition` (of the workspace the robot moves in) with random picks seeded by `seed`;
/// the other planners ignore both.
/// @throws std::invalid_argument for kPrmAcd without a decomposition.
std::shared_ptr<ompl::base::Planner> MakePlanner(
    PlannerType planner, const std::shared_ptr<ompl::base::SpaceInformation>& si,
    const acd::Decomposition2d* decomposition = nullptr, std::uint64_t seed = 1);

}  // namespace acdplan::planning
