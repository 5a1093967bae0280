// The exact states the ACD samplers draw from fixed seeds. Every draw goes through base/random.h
// (never std::*_distribution, whose output the standard leaves to each library), so these
// values hold with any standard library; a change of the distribution, of the order of the
// draws or of the seeding fails here. If the change is intended, update the values (hex-float
// literals: exact) and say so in the commit.

#include <gtest/gtest.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <cstdio>
#include <string>

#include "acd/decompose2d.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/acd_valid_state_sampler.h"
#include "planning/install_acd_samplers.h"
#include "tests/planning/point_free_space_checker.h"

namespace acdplan::planning {
namespace {

namespace ob = ompl::base;

struct Pinned {
  double x, y;
};

// AcdValidStateSampler on wall_gap (seed 1, gap 0.2 wide), tau = 0.02 x diagonal, default
// AcdSamplerOptions with seed 42: the first states (x, y).
const Pinned kFirstStates[] = {
    {0x1.473a27851e446p+2, 0x1.156989fb74442p+1}, {0x1.4296388fc3bb2p+2, 0x1.08134ee9a026bp+1},
    {0x1.0e386c2a14c64p+1, 0x1.1e7c88df94ee2p+3}, {0x1.5784f8240e6a9p+2, 0x1.1ea46da841255p+1},
    {0x1.ce69af802e4fp-1, 0x1.f8a73836961efp+2},
};
constexpr int kCount = static_cast<int>(sizeof(kFirstStates) / sizeof(kFirstStates[0]));

struct Fixture {
  envs::Workspace2d workspace = envs::GenerateWorkspace2d("wall_gap", 1, {0.2});
  std::vector<acd::Polygon2d> free_space = envs::FreeSpace2d(workspace);
  acd::Decomposition2d decomposition;
  ob::SpaceInformationPtr si;

  Fixture() {
    acd::Decompose2dOptions options;
    options.tau = 0.02 * workspace.bounds.sizes().norm();
    decomposition = acd::Decompose2d(free_space, options);
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds bounds(2);
    for (int i = 0; i < 2; ++i) {
      bounds.setLow(i, workspace.bounds.min()[i]);
      bounds.setHigh(i, workspace.bounds.max()[i]);
    }
    space->setBounds(bounds);
    si = std::make_shared<ob::SpaceInformation>(space);
    const std::vector<acd::Polygon2d>* fs = &free_space;
    si->setStateValidityChecker([fs](const ob::State* s) {
      const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
      return testing::InsideFreeSpace(*fs, Eigen::Vector2d(v[0], v[1]));
    });
    si->setup();
  }
};

/// The first kCount states of `sampler`, printed as hex floats when they differ from the pins.
void ExpectPinned(ob::ValidStateSampler& sampler, const ob::SpaceInformation& si,
                  const char* what) {
  ob::State* state = si.allocState();
  std::string drawn;
  bool same = true;
  for (int i = 0; i < kCount; ++i) {
    ASSERT_TRUE(sampler.sample(state)) << what << ": state " << i;
    const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    EXPECT_EQ(v[0], kFirstStates[i].x) << what << ": x of state " << i;
    EXPECT_EQ(v[1], kFirstStates[i].y) << what << ": y of state " << i;
    same = same && v[0] == kFirstStates[i].x && v[1] == kFirstStates[i].y;
    char line[128];
    std::snprintf(line, sizeof(line), "    {%a, %a},\n", v[0], v[1]);
    drawn += line;
  }
  si.freeState(state);
  if (!same) std::printf("%s drew:\n%s", what, drawn.c_str());
}

TEST(PinnedSamples, AcdValidStateSamplerFirstStates) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const Fixture f;
  AcdSamplerOptions options;
  options.seed = 42;
  AcdValidStateSampler sampler(f.si.get(), f.decomposition, options);
  ExpectPinned(sampler, *f.si, "AcdValidStateSampler");
}

TEST(PinnedSamples, FirstInstalledSamplerDrawsTheSame) {
  // InstallAcdSamplers(): the first sampler allocated gets DeriveSeed(seed, 0), as a sampler
  // constructed with that seed does.
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const Fixture f;
  AcdSamplerOptions options;
  options.seed = 42;
  InstallAcdSamplers(f.si, f.decomposition, options);
  ob::ValidStateSamplerPtr sampler = f.si->allocValidStateSampler();
  ExpectPinned(*sampler, *f.si, "InstallAcdSamplers");
}

}  // namespace
}  // namespace acdplan::planning
