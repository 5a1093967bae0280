// PRM_ACD (planning/acd_prm.h): component location, the registry entry, and the Figure-4
// protocol in a narrow zig-zag corridor, where PRM's nearest-neighbour connections leave the
// ACD sampler's clusters apart.

#include "planning/acd_prm.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "acd/decompose2d.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/plan_scenario.h"
#include "planning/registry.h"
#include "planning/scenario.h"
#include "tests/data_paths.h"

namespace acdplan::planning {
namespace {

namespace ob = ompl::base;

using acdplan::test::kConfigs;

std::shared_ptr<ob::SpaceInformation> Plane(const envs::Workspace2d& workspace) {
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int i = 0; i < 2; ++i) {
    bounds.setLow(i, workspace.bounds.min()[i]);
    bounds.setHigh(i, workspace.bounds.max()[i]);
  }
  space->setBounds(bounds);
  return std::make_shared<ob::SpaceInformation>(space);
}

TEST(AcdPrm, LocatesEveryCentroidInItsComponent) {
  const envs::Workspace2d world = envs::GenerateWorkspace2d("zigzag", 1, {0.2});
  acd::Decompose2dOptions options;
  options.tau = 0.02 * world.bounds.sizes().norm();
  const acd::Decomposition2d decomposition = acd::Decompose2d(envs::FreeSpace2d(world), options);
  ASSERT_GE(decomposition.components.size(), 3u);
  const AcdPrm prm(Plane(world), decomposition);
  for (size_t c = 0; c < decomposition.components.size(); ++c) {
    // Components are nearly convex, so their centroids lie inside them.
    EXPECT_EQ(prm.Locate(decomposition.components[c].centroid), static_cast<int>(c));
  }
  EXPECT_EQ(prm.Locate(world.bounds.max() + Eigen::Vector2d(1, 1)), -1);
}

TEST(AcdPrm, TheRegistryMakesItOnlyWithADecomposition) {
  const envs::Workspace2d world = envs::GenerateWorkspace2d("wall_gap", 1);
  EXPECT_THROW(MakePlanner(PlannerType::kPrmAcd, Plane(world)), std::invalid_argument);
  const acd::Decomposition2d decomposition = acd::Decompose2d(envs::FreeSpace2d(world));
  EXPECT_EQ(MakePlanner(PlannerType::kPrmAcd, Plane(world), &decomposition)->getName(), "PRM_ACD");
  EXPECT_TRUE(HonoursSampleBudget(PlannerType::kPrmAcd));
}

// The zig-zag corridor of configs/zigzag.yaml narrowed to 0.1, 300 collision-free samples, ten
// seeds (in a 20-run benchmark: 3 of 20 connected with PRM, 20 of 20 with PRM_ACD).
TEST(AcdPrm, ConnectsTheAcdSamplesOfANarrowCorridor) {
  Scenario s = LoadScenario(kConfigs + "/zigzag.yaml");
  s.workspace = envs::GenerateWorkspace2d("zigzag", 1, {0.1});
  s.samples = 300;
  s.sampler = SamplerType::kAcd;
  int prm = 0, prm_acd = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    s.seed = seed;
    s.planner = PlannerType::kPrm;
    prm += PlanScenario(s).solved;
    s.planner = PlannerType::kPrmAcd;
    const PlanResult result = PlanScenario(s);
    EXPECT_EQ(result.samples, 300u);
    if (result.solved) {
      ++prm_acd;
      EXPECT_GE(result.path.size(), 3u);
    }
  }
  std::printf("zigzag 0.1, acd sampler, 300 samples: PRM %d of 10, PRM_ACD %d of 10\n", prm,
              prm_acd);
  EXPECT_GE(prm_acd, 9);
  EXPECT_LT(prm, prm_acd);
}

}  // namespace
}  // namespace acdplan::planning
