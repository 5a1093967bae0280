#include "planning/control/plan_car.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/planners/est/EST.h>
#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/pdst/PDST.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/syclop/GridDecomposition.h>
#include <ompl/control/planners/syclop/SyclopEST.h>
#include <ompl/control/planners/syclop/SyclopRRT.h>

#include "base/input_error.h"
#include "base/stopwatch.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "planning/acd_decomposition.h"
#include "planning/decomposition_cache.h"

namespace acdplan::planning::control {

namespace ob = ompl::base;
namespace oc = ompl::control;

namespace {

ob::SE2StateSpace::StateType* Se2(CarModel model, ob::State* state) {
  return model == CarModel::kKinematic
             ? state->as<ob::SE2StateSpace::StateType>()
             : state->as<ob::CompoundStateSpace::StateType>()->as<ob::SE2StateSpace::StateType>(0);
}

/// OMPL's grid with the car's (x, y) as the projection.
class XyGrid : public oc::GridDecomposition {
 public:
  XyGrid(int cells, const ob::RealVectorBounds& bounds, CarModel model)
      : oc::GridDecomposition(cells, 2, bounds), model_(model) {}
  void project(const ob::State* s, std::vector<double>& coord) const override {
    const Eigen::Isometry2d pose = CarPose(model_, s);
    coord = {pose.translation().x(), pose.translation().y()};
  }
  void sampleFullState(const ob::StateSamplerPtr& sampler, const std::vector<double>& coord,
                       ob::State* s) const override {
    sampler->sampleUniform(s);
    Se2(model_, s)->setXY(coord[0], coord[1]);
  }

 private:
  CarModel model_;
};

/// A goal state reached when the position is within the threshold (heading, speed free).
class XyGoal : public ob::GoalState {
 public:
  XyGoal(const ob::SpaceInformationPtr& si, CarModel model) : ob::GoalState(si), model_(model) {}
  double distanceGoal(const ob::State* st) const override {
    return (CarPose(model_, st).translation() - CarPose(model_, state_).translation()).norm();
  }

 private:
  CarModel model_;
};

}  // namespace

ControlPlanner ParseControlPlanner(const std::string& name) {
  for (ControlPlanner p :
       {ControlPlanner::kSyclopRrt, ControlPlanner::kSyclopEst, ControlPlanner::kRrt,
        ControlPlanner::kKpiece1, ControlPlanner::kEst, ControlPlanner::kPdst}) {
    if (ToString(p) == name) return p;
  }
  throw InputError("unknown control planner '" + name +
                   "' (expected one of: SyclopRRT, SyclopEST, RRT, KPIECE1, EST, PDST)");
}

std::string ToString(ControlPlanner planner) {
  switch (planner) {
    case ControlPlanner::kSyclopRrt:
      return "SyclopRRT";
    case ControlPlanner::kSyclopEst:
      return "SyclopEST";
    case ControlPlanner::kRrt:
      return "RRT";
    case ControlPlanner::kKpiece1:
      return "KPIECE1";
    case ControlPlanner::kEst:
      return "EST";
    case ControlPlanner::kPdst:
      return "PDST";
  }
  return "?";
}

CarResult PlanCar(const CarQuery& query) {
  const Stopwatch stopwatch;
  CarResult result;
  auto obstacles =
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(query.workspace));
  auto world = std::make_shared<const collision::CollisionWorld>(
      obstacles, query.robot, collision::CollisionWorldOptions{});
  const envs::Robot robot = query.robot;
  const Eigen::AlignedBox2d box = query.workspace.bounds;
  oc::SpaceInformationPtr si = MakeCarSpaceInformation(
      query.model, box,
      [world, robot, box](const Eigen::Isometry2d& pose) {
        return envs::InsideBounds(robot, box, pose) && world->IsValid(pose);
      },
      query.car);

  ob::ScopedState<> start(si), goal(si);
  for (ob::ScopedState<>* s : {&start, &goal}) {
    for (unsigned i = 0; i < si->getStateDimension(); ++i) (*s)[i] = 0.0;
  }
  Se2(query.model, start.get())->setXY(query.start.x(), query.start.y());
  Se2(query.model, start.get())->setYaw(query.start.z());
  Se2(query.model, goal.get())->setXY(query.goal.x(), query.goal.y());
  if (!si->isValid(start.get())) {
    throw InputError("PlanCar(): start: the robot is in collision or out of bounds there");
  }
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->addStartState(start);
  auto goal_region = std::make_shared<XyGoal>(si, query.model);
  goal_region->setState(goal);
  goal_region->setThreshold(query.goal_radius);
  pdef->setGoal(goal_region);

  ob::RealVectorBounds xy(2);
  for (int i = 0; i < 2; ++i) {
    xy.setLow(i, box.min()[i]);
    xy.setHigh(i, box.max()[i]);
  }
  oc::DecompositionPtr decomposition;
  const bool syclop =
      query.planner == ControlPlanner::kSyclopRrt || query.planner == ControlPlanner::kSyclopEst;
  if (syclop) {
    if (query.decomposition == DecompositionKind::kAcd) {
      acd::Decompose2dOptions options;
      options.tau = query.tau_diag * box.sizes().norm();
      const CachedDecomposition cached = DecomposeFreeSpaceCached(query.workspace, options);
      result.decomposition_ms = cached.compute_ms;
      decomposition =
          std::make_shared<AcdDecomposition>(*cached.decomposition, xy, si->getStateSpace().get());
    } else {
      if (query.grid_cells < 1) throw InputError("PlanCar(): grid_cells must be >= 1");
      decomposition = std::make_shared<XyGrid>(query.grid_cells, xy, query.model);
    }
    result.regions = decomposition->getNumRegions();
  }
  ob::PlannerPtr planner;
  switch (query.planner) {
    case ControlPlanner::kSyclopRrt:
      planner = std::make_shared<oc::SyclopRRT>(si, decomposition);
      break;
    case ControlPlanner::kSyclopEst:
      planner = std::make_shared<oc::SyclopEST>(si, decomposition);
      break;
    case ControlPlanner::kRrt:
      planner = std::make_shared<oc::RRT>(si);
      break;
    case ControlPlanner::kKpiece1:
      planner = std::make_shared<oc::KPIECE1>(si);
      break;
    case ControlPlanner::kEst:
      planner = std::make_shared<oc::EST>(si);
      break;
    case ControlPlanner::kPdst:
      planner = std::make_shared<oc::PDST>(si);
      break;
  }
  planner->setProblemDefinition(pdef);
  planner->setup();
  const double remaining = std::max(1e-3, query.time_limit - stopwatch.Seconds());
  const ob::PlannerStatus status = planner->solve(remaining);
  // Syclop (OMPL 1.5) returns EXACT_SOLUTION with an approximate path when time runs out: ask
  // the problem definition whether the solution is exact.
  result.solved = status == ob::PlannerStatus::EXACT_SOLUTION && pdef->hasExactSolution();
  if (result.solved) {
    auto* path = pdef->getSolutionPath()->as<oc::PathControl>();
    result.path_duration = path->length();
    for (const ob::State* state : path->getStates()) {
      std::vector<double> reals;
      si->getStateSpace()->copyToReals(reals, state);
      result.path.push_back(reals);
    }
  }
  result.time_s = stopwatch.Seconds();
  return result;
}

}  // namespace acdplan::planning::control
