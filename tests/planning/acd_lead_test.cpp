// The ACD as a lead (planning/acd_lead_sampler.h, planning/internal/lead.h) and the
// decomposition cache (planning/decomposition_cache.h). Fixed seeds and draw counts; no
// wall-clock limits.

#include <gtest/gtest.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <cstdio>
#include <fstream>
#include <set>

#include "acd/component_locator2d.h"
#include "acd/decompose2d.h"
#include "base/input_error.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/acd_lead_sampler.h"
#include "planning/decomposition_cache.h"
#include "planning/internal/lead.h"
#include "planning/plan_scenario.h"
#include "planning/registry.h"
#include "planning/scenario.h"
#include "tests/planning/square_component.h"
#include "tests/scratch_dir.h"

namespace acdplan::planning {
namespace {

namespace ob = ompl::base;

acd::Decomposition2d Decompose(const envs::Workspace2d& workspace) {
  acd::Decompose2dOptions options;
  options.tau = 0.02 * workspace.bounds.sizes().norm();
  return acd::Decompose2d(envs::FreeSpace2d(workspace), options);
}

using testing::Square;

/// Four unit squares in a 2 x 2 block: 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1). Openings: 0-1 full,
/// 0-2 full, 1-3 full, 2-3 only 0.05 long (a slit).
acd::Decomposition2d Block() {
  acd::Decomposition2d d;
  d.components = {Square(0, 0, 1), Square(1, 0, 1), Square(0, 1, 1), Square(1, 1, 1)};
  d.openings = {{{1, 0}, {1, 1}, 0, 1},
                {{0, 1}, {1, 1}, 0, 2},
                {{1, 1}, {2, 1}, 1, 3},
                {{1, 1.5}, {1, 1.55}, 2, 3}};
  return d;
}

TEST(FindLead, ShortestChainThroughOpenings) {
  const acd::Decomposition2d d = Block();
  // 2 -> 3: the slit is shortest (1.0) for a point; around through 0 and 1 costs 3 x 1.0.
  const internal::Lead direct = internal::FindLead(d, 2, 3, 0.0, 100.0);
  EXPECT_EQ(direct.components, (std::vector<int>{2, 3}));
  EXPECT_EQ(direct.openings, (std::vector<int>{3}));
  // A robot 0.1 wide does not fit the 0.05 slit: penalised x 100, the lead goes around.
  const internal::Lead around = internal::FindLead(d, 2, 3, 0.1, 100.0);
  EXPECT_EQ(around.components, (std::vector<int>{2, 0, 1, 3}));
  EXPECT_EQ(around.openings, (std::vector<int>{1, 0, 2}));
  EXPECT_NEAR(around.cost, 3.0, 1e-12);
  // Same component: a lead of one.
  EXPECT_EQ(internal::FindLead(d, 1, 1, 0.0, 100.0).components, (std::vector<int>{1}));
}

TEST(FindLead, UnreachableGoalGivesInfiniteCost) {
  acd::Decomposition2d d = Block();
  d.openings.clear();
  const internal::Lead lead = internal::FindLead(d, 0, 3, 0.0, 100.0);
  EXPECT_EQ(lead.components, (std::vector<int>{0, 3}));
  EXPECT_TRUE(lead.openings.empty());
  EXPECT_FALSE(lead.cost < 1e300);
}

/// Checks that `lead` is a chain: consecutive components joined by the listed openings.
void ExpectChain(const acd::Decomposition2d& d, const internal::Lead& lead) {
  ASSERT_EQ(lead.openings.size() + 1, lead.components.size());
  for (size_t i = 0; i < lead.openings.size(); ++i) {
    const acd::Opening2d& o = d.openings[lead.openings[i]];
    const std::set<int> ends = {o.component_a, o.component_b};
    EXPECT_EQ(ends, (std::set<int>{lead.components[i], lead.components[i + 1]})) << i;
  }
}

TEST(FindLead, ZigzagCorridorLeadIsTheWholeCorridorInOrder) {
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d("zigzag", 1, {0.5});
  const acd::Decomposition2d d = Decompose(workspace);
  const int from = internal::LocateComponent(d, {0.3, 5.0});
  const int to = internal::LocateComponent(d, {9.7, 5.0});
  const internal::Lead lead = internal::FindLead(d, from, to, 0.2, 100.0);
  ExpectChain(d, lead);
  // One corridor: every component lies on the way, each once.
  EXPECT_EQ(lead.components.size(), d.components.size());
  EXPECT_EQ(std::set<int>(lead.components.begin(), lead.components.end()).size(),
            d.components.size());
  EXPECT_EQ(lead.components.front(), from);
  EXPECT_EQ(lead.components.back(), to);
}

TEST(FindLead, TwoRoomsLeadGoesThroughTheDoor) {
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d("two_rooms", 1, {0.6});
  const acd::Decomposition2d d = Decompose(workspace);
  const Eigen::Vector2d start(3.0, 4.0), goal(9.0, 3.0);
  const acd::ComponentLocator2d locator(d);
  const internal::Lead lead =
      internal::FindLead(d, locator.Locate(start), locator.Locate(goal), 0.3, 100.0);
  ExpectChain(d, lead);
  ASSERT_GE(lead.components.size(), 2u);
  EXPECT_EQ(lead.components.front(), locator.Locate(start));
  EXPECT_EQ(lead.components.back(), locator.Locate(goal));
  // The lead leaves the start's room: some opening of it is the door, between x of the start
  // and of the goal (the rooms are side by side).
  bool crosses = false;
  for (int o : lead.openings) {
    const double x = 0.5 * (d.openings[o].a.x() + d.openings[o].b.x());
    crosses = crosses || (x > start.x() && x < goal.x());
  }
  EXPECT_TRUE(crosses);
  // Shorter than the whole graph: the lead is a selection, not everything.
  EXPECT_LT(lead.components.size(), d.components.size());
}

TEST(RobotWidth, PointDiscAndBar) {
  EXPECT_EQ(RobotWidth(envs::Robot::Point()), 0.0);
  EXPECT_DOUBLE_EQ(RobotWidth(envs::Robot::Disc(0.1)), 0.2);
  acd::Polygon2d bar;
  bar.outer = {{-0.2, -0.05}, {0.2, -0.05}, {0.2, 0.05}, {-0.2, 0.05}};
  EXPECT_NEAR(RobotWidth(envs::Robot::Polygon(bar)), 0.1, 1e-12);
  // An L: the narrowest direction is across its hull's diagonal edge (x + y = 2.2), which no
  // edge of the outline lies on; the outline's own edges would give 0.2.
  acd::Polygon2d l;
  l.outer = {{0, 0}, {2, 0}, {2, 0.2}, {0.2, 0.2}, {0.2, 2}, {0, 2}};
  EXPECT_NEAR(RobotWidth(envs::Robot::Polygon(l)), 2.2 / std::sqrt(2.0), 1e-12);
}

/// A point space over `workspace`'s bounds (no validity checks: the distribution itself).
ob::SpaceInformationPtr PointSpace(const envs::Workspace2d& workspace) {
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int i = 0; i < 2; ++i) {
    bounds.setLow(i, workspace.bounds.min()[i]);
    bounds.setHigh(i, workspace.bounds.max()[i]);
  }
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker([](const ob::State*) { return true; });
  si->setup();
  return si;
}

struct MazeFixture : ::testing::Test {
  envs::Workspace2d workspace = envs::GenerateWorkspace2d("maze", 1, {1.0});
  acd::Decomposition2d decomposition = Decompose(workspace);
  AcdLeadQuery query{{0.75, 0.75}, {9.5, 9.5}, 0.2};
};

TEST_F(MazeFixture, SamplesConcentrateOnTheLeadThenWiden) {
  AcdSamplerOptions options;
  options.seed = 7;
  options.uniform_share = 0.1;
  auto lead = std::make_shared<const internal::LeadDistribution>(decomposition, query, options,
                                                                 AcdLeadOptions{});
  const std::vector<int> level0 = lead->ComponentsAt(0), level1 = lead->ComponentsAt(1);
  ASSERT_LT(level0.size(), level1.size());
  ASSERT_LT(level1.size(), decomposition.components.size());
  const std::set<int> on_lead(level0.begin(), level0.end());
  const std::set<int> near_lead(level1.begin(), level1.end());
  const acd::ComponentLocator2d locator(decomposition);
  const ob::SpaceInformationPtr si = PointSpace(workspace);
  AcdLeadStateSampler sampler(si->getStateSpace().get(), lead, 11);
  ob::State* state = si->allocState();
  const std::uint64_t stage = lead->stage_draws();
  int in_lead = 0, off_lead_targeted = 0, in_neighbours = 0, beyond = 0;
  for (std::uint64_t i = 0; i < 5 * stage; ++i) {
    EXPECT_EQ(sampler.level(), i < stage ? 0 : i < 3 * stage ? 1 : 2);
    sampler.sampleUniform(state);
    const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    const int c = locator.Locate({v[0], v[1]});
    const bool targeted = sampler.last_part() != AcdLeadStateSampler::kUniformPart;
    if (i < stage) {
      in_lead += on_lead.count(c) ? 1 : 0;
      // A targeted component draw lies in a lead component (opening draws may spill over).
      if (targeted && sampler.last_part() >= 0 && !on_lead.count(c)) ++off_lead_targeted;
    } else if (i < 3 * stage) {
      in_neighbours += near_lead.count(c) && !on_lead.count(c) ? 1 : 0;
    } else {
      beyond += !near_lead.count(c) && c >= 0 ? 1 : 0;
    }
  }
  si->freeState(state);
  EXPECT_EQ(off_lead_targeted, 0);
  // Level 0: the lead holds level0.size() of the components but ~all targeted draws.
  const double lead_share = static_cast<double>(in_lead) / static_cast<double>(stage);
  const double lead_area_share = [&] {
    double a = 0, all = 0;
    for (size_t c = 0; c < decomposition.components.size(); ++c) {
      const double area = std::abs(acd::Area(decomposition.components[c].polygon));
      all += area;
      if (on_lead.count(static_cast<int>(c))) a += area;
    }
    return a / all;
  }();
  EXPECT_GT(lead_share, 0.85);
  EXPECT_GT(lead_share, lead_area_share + 0.2);
  // Widening: level 1 puts draws in the neighbours, level 2 beyond them.
  EXPECT_GT(in_neighbours, 0);
  EXPECT_GT(beyond, 0);
}

TEST_F(MazeFixture, SameSeedSameSamples) {
  AcdSamplerOptions options;
  auto lead = std::make_shared<const internal::LeadDistribution>(decomposition, query, options,
                                                                 AcdLeadOptions{});
  const ob::SpaceInformationPtr si = PointSpace(workspace);
  AcdLeadStateSampler a(si->getStateSpace().get(), lead, 5), b(si->getStateSpace().get(), lead, 5),
      c(si->getStateSpace().get(), lead, 6);
  ob::State *sa = si->allocState(), *sb = si->allocState(), *sc = si->allocState();
  int differ = 0;
  for (int i = 0; i < 2000; ++i) {
    a.sampleUniform(sa), b.sampleUniform(sb), c.sampleUniform(sc);
    ASSERT_TRUE(si->getStateSpace()->equalStates(sa, sb)) << i;
    differ += si->getStateSpace()->equalStates(sa, sc) ? 0 : 1;
  }
  EXPECT_GT(differ, 1900);
  si->freeState(sa), si->freeState(sb), si->freeState(sc);
}

TEST(DecompositionCache, SameMapHitsOtherOptionsMiss) {
  ClearDecompositionCache();
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d("zigzag", 1, {0.5});
  acd::Decompose2dOptions options;
  options.tau = 0.2;
  const CachedDecomposition first = DecomposeFreeSpaceCached(workspace, options);
  EXPECT_FALSE(first.hit);
  EXPECT_GT(first.compute_ms, 0.0);
  const CachedDecomposition second = DecomposeFreeSpaceCached(workspace, options);
  EXPECT_TRUE(second.hit);
  EXPECT_EQ(second.decomposition.get(), first.decomposition.get());
  EXPECT_EQ(second.compute_ms, first.compute_ms);  // The cost is still reported.
  options.tau = 0.3;
  EXPECT_FALSE(DecomposeFreeSpaceCached(workspace, options).hit);
  envs::Workspace2d moved = workspace;
  moved.obstacles[0].outer[0].x() += 1e-9;
  options.tau = 0.2;
  EXPECT_FALSE(DecomposeFreeSpaceCached(moved, options).hit);
  ClearDecompositionCache();
  EXPECT_FALSE(DecomposeFreeSpaceCached(workspace, options).hit);
}

TEST(AcdLeadScenario, LeadKeyAndRegisteredName) {
  EXPECT_EQ(ParseSamplerType("acd_lead"), SamplerType::kAcdLead);
  EXPECT_EQ(ToString(SamplerType::kAcdLead), "acd_lead");
  const test::ScratchDir dir("acdplan_acd_lead_test");
  const std::string path = dir.Path("acd_lead_scenario.yaml");
  auto write = [&path](const std::string& sampler) {
    std::ofstream(path) << "workspace: {generator: zigzag, passage_width: 0.5}\n"
                           "robot: {shape: disc, radius: 0.1}\n"
                           "start: [0.3, 5.0]\ngoal: [9.7, 5.0]\n"
                           "planner: {name: PRM, samples: 100}\n"
                        << "sampler: " << sampler << "\nseed: 3\n";
  };
  write("{name: acd, lead: true}");
  const Scenario scenario = LoadScenario(path);
  EXPECT_EQ(scenario.sampler, SamplerType::kAcdLead);
  write("{name: uniform, lead: true}");
  try {
    LoadScenario(path);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("sampler.lead: only for the acd sampler"),
              std::string::npos)
        << error.what();
  }
  // The lead solves the 100-sample zigzag query with this seed; same seed, same roadmap.
  const PlanResult a = PlanScenario(scenario);
  const PlanResult b = PlanScenario(scenario);
  EXPECT_TRUE(a.solved);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_TRUE(b.decomposition_cached);
  EXPECT_EQ(a.decomposition_compute_ms, b.decomposition_compute_ms);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace acdplan::planning
