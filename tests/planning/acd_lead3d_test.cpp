// The ACD as a lead in 3D worlds (planning/acd_lead_sampler3d.h, planning/internal/lead3d.h):
// the lead chain up the cubicles, the narrowness penalty, the draws of the first stage on the
// lead, determinism, and acd_lead through the window wall. Fixed seeds; no wall-clock limits.

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <set>

#include "envs/free_space_decomposition3d.h"
#include "envs/generators3d.h"
#include "planning/acd_decomposition3d.h"
#include "planning/acd_lead_sampler3d.h"
#include "planning/internal/lead3d.h"
#include "planning/plan_scenario.h"
#include "planning/scenario.h"
#include "tests/asan_build.h"
#include "tests/envs/test_worlds3d.h"
#include "tests/scratch_dir.h"

namespace acdplan::planning {
namespace {

namespace fs = std::filesystem;
namespace ob = ompl::base;

// Every test decomposes into its own scratch cache, never the user's.
class Lead3d : public ::testing::Test {
 protected:
  void SetUp() override { setenv("ACDPLAN_CACHE_DIR", (dir_ / "cache").c_str(), 1); }
  void TearDown() override { unsetenv("ACDPLAN_CACHE_DIR"); }
  test::ScratchDir scratch_{"acdplan_lead3d"};
  fs::path dir_ = scratch_.path();
};

// The cubicles of configs/cubicles_3d.yaml: three rooms stacked, hatches of side 1.
struct Cubicles {
  envs::Workspace3d world;
  envs::Passages3d hatches;
  envs::FreeSpaceDecomposition3d acd;
};

Cubicles MakeCubicles() {
  Cubicles c;
  c.world = envs::MakeCubicles(1, {}, &c.hatches);
  envs::FreeSpaceDecomposition3dOptions options;
  options.tau = 0.03 * c.world.bounds.sizes().norm();
  c.acd = envs::DecomposeFreeSpace3d(c.world, options);
  return c;
}

const Eigen::Vector3d kBottom(5, 5, 1.5), kTop(5, 5, 7.5);

TEST_F(Lead3d, ChainUpTheCubiclesPassesEveryHatch) {
  const Cubicles c = MakeCubicles();
  ASSERT_EQ(c.hatches.size(), 2u);
  const int from = internal::LocateComponent3d(c.acd, kBottom);
  const int to = internal::LocateComponent3d(c.acd, kTop);
  ASSERT_NE(from, to);
  const internal::Lead lead = internal::FindLead3d(c.acd, from, to, 0.0, 100.0);
  ASSERT_TRUE(std::isfinite(lead.cost));
  ASSERT_EQ(lead.openings.size() + 1, lead.components.size());
  EXPECT_EQ(lead.components.front(), from);
  EXPECT_EQ(lead.components.back(), to);
  // Consecutive components are the two sides of the opening between them.
  for (size_t i = 0; i < lead.openings.size(); ++i) {
    const envs::FreeOpening3d& o = c.acd.openings[static_cast<size_t>(lead.openings[i])];
    const std::set<int> ends{o.component_a, o.component_b};
    EXPECT_EQ(ends, (std::set<int>{lead.components[i], lead.components[i + 1]})) << i;
  }
  // Every hatch is on the way: its centre lies in a lead component, or a lead opening's
  // centroid lies in the hatch (the ACD cuts through it).
  const std::set<int> on_lead(lead.components.begin(), lead.components.end());
  for (const envs::Passage3d& hatch : c.hatches) {
    Eigen::AlignedBox3d box = hatch.box;
    box.extend(box.min() - Eigen::Vector3d::Constant(0.01));
    box.extend(box.max() + Eigen::Vector3d::Constant(0.01));
    bool passed = on_lead.count(c.acd.Locate(hatch.box.center())) > 0;
    for (int o : lead.openings) {
      passed = passed || box.contains(c.acd.openings[static_cast<size_t>(o)].centroid);
    }
    EXPECT_TRUE(passed) << "hatch at z " << hatch.box.min().z();
  }
  // The point's lead takes the shortest way, through a sliver cut if there is one; a body 0.3
  // wide (the short rod of configs/cubicles_3d.yaml) is led round every opening narrower than
  // itself, at a cost no lower than the point's.
  double narrowest = std::numeric_limits<double>::infinity();
  for (int o : lead.openings) {
    narrowest = std::min(narrowest, c.acd.openings[static_cast<size_t>(o)].width);
  }
  const internal::Lead rod = internal::FindLead3d(c.acd, from, to, 0.3, 100.0);
  ASSERT_TRUE(std::isfinite(rod.cost));
  EXPECT_GE(rod.cost, lead.cost);
  for (int o : rod.openings) {
    EXPECT_GE(c.acd.openings[static_cast<size_t>(o)].width, 0.3) << o;
  }
  if (narrowest < 0.3) {
    EXPECT_NE(rod.components, lead.components);
  }
  // Nor through a component thinner than the rod (the 0.17-thick sliver the ACD cuts beside
  // the first hatch).
  for (int k : rod.components) {
    EXPECT_GE(internal::RobotWidth3d(c.acd.components[static_cast<size_t>(k)].hull.vertices), 0.3)
        << k;
  }
  // A body wider than every hatch pays the penalty whichever way it goes.
  EXPECT_GT(internal::FindLead3d(c.acd, from, to, 2.0, 100.0).cost, 10 * lead.cost);
}

TEST_F(Lead3d, RobotWidthIsTheSmallestExtent) {
  const acd::TriangleMesh rod = envs::testing::BoxMesh({-1.5, -0.25, -0.3}, {1.5, 0.25, 0.3});
  EXPECT_NEAR(internal::RobotWidth3d(rod.vertices), 0.5, 1e-9);
}

// An SE(3) space over the cubicles with the lead samplers of a 1.5 x 0.3 x 0.3 rod.
std::shared_ptr<ob::SpaceInformation> LeadSpace(const Cubicles& c, std::uint64_t seed) {
  auto space = std::make_shared<ob::SE3StateSpace>();
  ob::RealVectorBounds bounds(3);
  for (int i = 0; i < 3; ++i) {
    bounds.setLow(i, c.world.bounds.min()[i]);
    bounds.setHigh(i, c.world.bounds.max()[i]);
  }
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker([](const ob::State*) { return true; });
  si->setup();
  AcdSamplerOptions options;
  options.seed = seed;
  options.orientation = AcdOrientation::kAligned;
  const acd::TriangleMesh rod = envs::testing::BoxMesh({-0.75, -0.15, -0.15}, {0.75, 0.15, 0.15});
  InstallAcdLeadSamplers3d(si, c.acd, {kBottom, kTop}, options, {}, &rod);
  return si;
}

TEST_F(Lead3d, FirstStageDrawsFollowTheLeadAndAreSeeded) {
  const Cubicles c = MakeCubicles();
  const internal::Lead lead =
      internal::FindLead3d(c.acd, internal::LocateComponent3d(c.acd, kBottom),
                           internal::LocateComponent3d(c.acd, kTop), 0.3, 100.0);
  const std::set<int> components(lead.components.begin(), lead.components.end());
  const std::set<int> openings(lead.openings.begin(), lead.openings.end());

  auto si = LeadSpace(c, 7);
  auto sampler = si->allocStateSampler();
  auto* lead_sampler = dynamic_cast<AcdLeadStateSampler3d*>(sampler.get());
  ASSERT_NE(lead_sampler, nullptr);
  ob::ScopedState<ob::SE3StateSpace> state(si);
  int on_components = 0, on_openings = 0;
  std::vector<double> xs;
  while (lead_sampler->level() == 0) {
    sampler->sampleUniform(state.get());
    xs.push_back(state->getX());
    const int part = lead_sampler->last_part();
    if (part == AcdLeadStateSampler::kUniformPart) continue;
    if (part >= 0) {
      ++on_components;
      EXPECT_TRUE(components.count(part)) << part;
      // Inside the component's hull.
      const Eigen::Vector3d p(state->getX(), state->getY(), state->getZ());
      EXPECT_TRUE(internal::HullSampler3d(c.acd.components[static_cast<size_t>(part)]).Contains(p));
    } else {
      ++on_openings;
      EXPECT_TRUE(openings.count(-1 - part)) << part;
      // The rod's long axis within 45 degrees of the opening's normal.
      const Eigen::Quaterniond q(state->rotation().w, state->rotation().x, state->rotation().y,
                                 state->rotation().z);
      const Eigen::Vector3d n = c.acd.openings[static_cast<size_t>(-1 - part)].normal;
      EXPECT_GT(std::abs((q * Eigen::Vector3d::UnitX()).dot(n)), std::sqrt(0.5));
    }
  }
  EXPECT_GT(on_components, 50);
  EXPECT_GT(on_openings, 50);

  // The same seed draws the same states; another seed others.
  auto si_again = LeadSpace(c, 7), si_other = LeadSpace(c, 8);  // Own their spaces.
  auto again = si_again->allocStateSampler();
  auto other = si_other->allocStateSampler();
  ob::ScopedState<ob::SE3StateSpace> s1(si), s2(si);
  int same = 0, differ = 0;
  for (double x : xs) {
    again->sampleUniform(s1.get());
    other->sampleUniform(s2.get());
    same += s1->getX() == x;
    differ += s2->getX() != x;
  }
  EXPECT_EQ(same, static_cast<int>(xs.size()));
  EXPECT_GT(differ, static_cast<int>(xs.size()) - 5);
}

// acd_lead on the window wall of tests/planning/plan3d_test.cpp (a 2 x 0.2 x 0.2 rod, window of
// side 0.4 in a 1-thick wall), 150 collision-free samples: as acd, >= 9 of 10 seeds with PRM or
// PRM_ACD (uniform PRM connects <= 1 there, plan3d_test).
int LeadSolvedSeeds(PlannerType planner) {
  int solved = 0;
  for (int seed = 1; seed <= acdplan::test::kRateSeeds; ++seed) {
    Scenario s;
    s.dimension = 3;
    s.workspace3d = envs::testing::WindowWall(0.4);
    s.robot = envs::Robot::Mesh(envs::testing::BoxMesh({-1, -0.1, -0.1}, {1, 0.1, 0.1}));
    s.start = {2, 3, 3, 0, 0, M_PI / 2};
    s.goal = {8, 7, 7, 0, M_PI / 2, 0};
    s.sampler = SamplerType::kAcdLead;
    s.planner = planner;
    s.samples = 150;
    s.seed = seed;
    s.sampler_options.orientation = AcdOrientation::kAligned;
    s.sampler_options.aligned_jitter = 0.05;
    s.tau_diag = 0.1;
    solved += PlanScenario(s).solved;
  }
  return solved;
}

TEST_F(Lead3d, WindowWallLeadConnects) {
  const int prm = LeadSolvedSeeds(PlannerType::kPrm);
  const int prm_acd = LeadSolvedSeeds(PlannerType::kPrmAcd);
  const int seeds = acdplan::test::kRateSeeds;
  std::printf("acd_lead, 150 samples: PRM %d/%d, PRM_ACD %d/%d\n", prm, seeds, prm_acd, seeds);
  EXPECT_GE(std::max(prm, prm_acd), seeds - 1);
}

// The 3D ACD as Syclop's regions: the cubicles' components, their volumes and adjacency, the
// region of a state, and region samples inside their region.
TEST_F(Lead3d, AcdDecomposition3dRegions) {
  const Cubicles c = MakeCubicles();
  auto space = std::make_shared<ob::SE3StateSpace>();
  ob::RealVectorBounds bounds(3);
  for (int i = 0; i < 3; ++i) {
    bounds.setLow(i, c.world.bounds.min()[i]);
    bounds.setHigh(i, c.world.bounds.max()[i]);
  }
  space->setBounds(bounds);
  AcdDecomposition3d regions(c.acd, bounds, space.get());
  ASSERT_EQ(regions.getNumRegions(), static_cast<int>(c.acd.components.size()));
  double volume = 0;
  for (int r = 0; r < regions.getNumRegions(); ++r) volume += regions.getRegionVolume(r);
  EXPECT_NEAR(volume, c.acd.free_volume, 1e-6 * c.acd.free_volume);

  // Neighbours are symmetric and are the openings' ends.
  for (const envs::FreeOpening3d& o : c.acd.openings) {
    std::vector<int> a, b;
    regions.getNeighbors(o.component_a, a);
    regions.getNeighbors(o.component_b, b);
    EXPECT_TRUE(std::count(a.begin(), a.end(), o.component_b));
    EXPECT_TRUE(std::count(b.begin(), b.end(), o.component_a));
  }

  // A state in the bottom room and one in the top room: different regions, those of the lead.
  ob::ScopedState<ob::SE3StateSpace> state(space);
  state->setXYZ(kBottom.x(), kBottom.y(), kBottom.z());
  state->rotation().setIdentity();
  EXPECT_EQ(regions.locateRegion(state.get()), c.acd.Locate(kBottom));
  state->setXYZ(kTop.x(), kTop.y(), kTop.z());
  EXPECT_EQ(regions.locateRegion(state.get()), c.acd.Locate(kTop));
  EXPECT_NE(c.acd.Locate(kBottom), c.acd.Locate(kTop));
  state->setXYZ(5, 5, 20);  // Above the world: in no hull.
  EXPECT_EQ(regions.locateRegion(state.get()), -1);

  // Region samples lie in their region; the full state keeps them.
  ompl::RNG rng(3);
  auto sampler = space->allocDefaultStateSampler();
  std::vector<double> coord;
  for (int r = 0; r < regions.getNumRegions(); ++r) {
    for (int i = 0; i < 20; ++i) {
      regions.sampleFromRegion(r, rng, coord);
      ASSERT_EQ(coord.size(), 3u);
      const Eigen::Vector3d p(coord[0], coord[1], coord[2]);
      EXPECT_TRUE(internal::HullSampler3d(c.acd.components[static_cast<size_t>(r)]).Contains(p))
          << r;
      regions.sampleFullState(sampler, coord, state.get());
      std::vector<double> back;
      regions.project(state.get(), back);
      EXPECT_EQ(back, coord);
    }
  }
}

}  // namespace
}  // namespace acdplan::planning
