// AcdDecomposition (planning/acd_decomposition.h) against hand-built decompositions and a
// generated maze; and SyclopRRT using it on a simple control system. Fixed seeds and
// iteration budgets; no wall-clock limits.

#include "planning/acd_decomposition.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/control/SpaceInformation.h>
#include <ompl/control/planners/syclop/SyclopRRT.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <stdexcept>

#include "acd/decompose2d.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/internal/component_sampler.h"
#include "tests/planning/square_component.h"

namespace acdplan::planning {
namespace {

namespace ob = ompl::base;
namespace oc = ompl::control;

using testing::Square;

/// Region 0: an L (the unit square [0,2]^2 minus [1,2]x[1,2]), area 3, hull area 3.5.
/// Region 1: the square [2,3]x[0,1] right of it. Region 2: the square [0,1]x[2,3] above it.
/// Openings: 0-1 along x = 2, 0-2 along y = 2.
acd::Decomposition2d LBlock() {
  acd::Decomposition2d d;
  acd::Component2d l;
  l.polygon.outer = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  l.hull = {{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 2}};
  l.centroid = Eigen::Vector2d(5.0 / 6, 5.0 / 6);
  d.components = {l, Square(2, 0, 1), Square(0, 2, 1)};
  d.openings = {{{2, 0}, {2, 1}, 0, 1}, {{0, 2}, {1, 2}, 0, 2}};
  return d;
}

ob::RealVectorBounds Bounds(double low, double high) {
  ob::RealVectorBounds bounds(2);
  bounds.setLow(low);
  bounds.setHigh(high);
  return bounds;
}

// SyclopRRT with the ACD of the zigzag corridor as its decomposition, on a point that moves
// with its velocity control (x' = u): the lead search and region sampling run through every
// member below. An iteration budget, not a clock. First in the file: it seeds OMPL's global
// generator, which only takes effect before any other OMPL sampler exists.
TEST(AcdDecomposition, SyclopRrtSolvesTheZigzagWithIt) {
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d("zigzag", 1, {0.5});
  acd::Decompose2dOptions options;
  options.tau = 0.02 * workspace.bounds.sizes().norm();
  const acd::Decomposition2d acd = acd::Decompose2d(envs::FreeSpace2d(workspace), options);
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int i = 0; i < 2; ++i) {
    bounds.setLow(i, workspace.bounds.min()[i]);
    bounds.setHigh(i, workspace.bounds.max()[i]);
  }
  space->setBounds(bounds);
  auto controls = std::make_shared<oc::RealVectorControlSpace>(space, 2);
  controls->setBounds(Bounds(-1, 1));
  auto si = std::make_shared<oc::SpaceInformation>(space, controls);
  auto decomposition = std::make_shared<AcdDecomposition>(acd, bounds, space.get());
  si->setStateValidityChecker([decomposition](const ob::State* s) {
    return decomposition->locateRegion(s) >= 0;  // In the free space.
  });
  si->setStatePropagator(
      [](const ob::State* from, const oc::Control* u, double duration, ob::State* to) {
        const double* x = from->as<ob::RealVectorStateSpace::StateType>()->values;
        const double* v = u->as<oc::RealVectorControlSpace::ControlType>()->values;
        double* y = to->as<ob::RealVectorStateSpace::StateType>()->values;
        y[0] = x[0] + duration * v[0];
        y[1] = x[1] + duration * v[1];
      });
  si->setPropagationStepSize(0.05);
  si->setMinMaxControlDuration(1, 10);
  si->setup();
  ompl::RNG::setSeed(7);
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  ob::ScopedState<> start(space), goal(space);
  start[0] = 0.3, start[1] = 5.0, goal[0] = 9.7, goal[1] = 5.0;
  pdef->setStartAndGoalStates(start, goal, 0.3);
  oc::SyclopRRT planner(si, decomposition);
  planner.setProblemDefinition(pdef);
  planner.setup();
  int iterations = 0;
  const ob::PlannerStatus status = planner.solve(
      ob::PlannerTerminationCondition([&iterations] { return ++iterations > 2000000; }));
  EXPECT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION);
}

TEST(AcdDecomposition, RegionsVolumesNeighbours) {
  ob::SE2StateSpace space;
  AcdDecomposition d(LBlock(), Bounds(0, 3), &space);
  EXPECT_EQ(d.getNumRegions(), 3);
  EXPECT_EQ(d.getDimension(), 2);
  EXPECT_DOUBLE_EQ(d.getRegionVolume(0), 3.0);
  EXPECT_DOUBLE_EQ(d.getRegionVolume(1), 1.0);
  std::vector<int> n;
  d.getNeighbors(0, n);
  EXPECT_EQ(n, (std::vector<int>{1, 2}));
  d.getNeighbors(1, n);
  EXPECT_EQ(n, (std::vector<int>{0}));
  d.getNeighbors(2, n);
  EXPECT_EQ(n, (std::vector<int>{0}));
}

TEST(AcdDecomposition, LocatesByExactPointLocation) {
  ob::SE2StateSpace space;
  AcdDecomposition d(LBlock(), Bounds(0, 3), &space);
  ob::State* s = space.allocState();
  auto at = [&](double x, double y) {
    s->as<ob::SE2StateSpace::StateType>()->setXY(x, y);
    s->as<ob::SE2StateSpace::StateType>()->setYaw(0.7);
    return d.locateRegion(s);
  };
  EXPECT_EQ(at(0.5, 0.5), 0);
  EXPECT_EQ(at(1.5, 0.5), 0);
  EXPECT_EQ(at(0.5, 1.5), 0);
  EXPECT_EQ(at(2.5, 0.5), 1);
  EXPECT_EQ(at(0.5, 2.5), 2);
  // Inside the L's hull but outside the L (and every other region): an obstacle.
  EXPECT_EQ(at(1.2, 1.2), -1);
  EXPECT_EQ(at(2.5, 2.5), -1);
  std::vector<double> coord;
  s->as<ob::SE2StateSpace::StateType>()->setXY(0.25, 1.75);
  d.project(s, coord);
  EXPECT_EQ(coord, (std::vector<double>{0.25, 1.75}));
  space.freeState(s);
}

TEST(AcdDecomposition, SamplesUniformlyInsideTheComponentNotItsHull) {
  ob::RealVectorStateSpace space(2);
  AcdDecomposition d(LBlock(), Bounds(0, 3), &space);
  ompl::RNG rng(42);
  int lower_right = 0, upper_left = 0, n = 6000;
  for (int i = 0; i < n; ++i) {
    std::vector<double> c;
    d.sampleFromRegion(0, rng, c);
    ASSERT_EQ(c.size(), 2u);
    ASSERT_EQ(d.LocatePoint({c[0], c[1]}), 0) << c[0] << " " << c[1];
    ASSERT_FALSE(c[0] > 1 && c[1] > 1) << "in the hull, outside the L";
    lower_right += c[0] > 1 ? 1 : 0;
    upper_left += c[1] > 1 ? 1 : 0;
  }
  // Uniform over the L: each of its three unit squares holds a third of the samples.
  EXPECT_NEAR(lower_right / static_cast<double>(n), 1.0 / 3, 0.03);
  EXPECT_NEAR(upper_left / static_cast<double>(n), 1.0 / 3, 0.03);
}

TEST(AcdDecomposition, SampleFullStateKeepsTheCoordinate) {
  auto se2 = std::make_shared<ob::SE2StateSpace>();
  se2->setBounds(Bounds(0, 3));
  auto velocity = std::make_shared<ob::RealVectorStateSpace>(2);
  velocity->setBounds(Bounds(-1, 1));
  auto car = std::make_shared<ob::CompoundStateSpace>();
  car->addSubspace(se2, 1.0);
  car->addSubspace(velocity, 0.3);
  car->lock();
  AcdDecomposition d(LBlock(), Bounds(0, 3), car.get());
  ob::StateSamplerPtr sampler = car->allocStateSampler();
  ob::State* s = car->allocState();
  d.sampleFullState(sampler, {2.5, 0.25}, s);
  std::vector<double> coord;
  d.project(s, coord);
  EXPECT_EQ(coord, (std::vector<double>{2.5, 0.25}));
  EXPECT_EQ(d.locateRegion(s), 1);
  car->freeState(s);
}

TEST(AcdDecomposition, RejectsSpacesWithoutXyAndEmptyDecompositions) {
  ob::RealVectorStateSpace line(1);
  EXPECT_THROW(AcdDecomposition(LBlock(), Bounds(0, 3), &line), std::invalid_argument);
  ob::SE2StateSpace se2;
  EXPECT_THROW(AcdDecomposition(acd::Decomposition2d{}, Bounds(0, 3), &se2), std::invalid_argument);
}

}  // namespace
}  // namespace acdplan::planning
