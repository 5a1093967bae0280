#include "planning/control/plan_car.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/planners/est/EST.h>
#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/pdst/PDST.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/syclop/GridDecomposition.h>
#include <ompl/control/planners/syclop/SyclopEST.h>
#include <ompl/control/planners/syclop/SyclopRRT.h>

#include <atomic>

#include "base/input_error.h"
#include "base/stopwatch.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "planning/acd_decomposition.h"
#include "planning/decomposition_cache.h"
#include "planning/tau_diag.h"

namespace acdplan::planning::control {

namespace ob = ompl::base;
namespace oc = ompl::control;

namespace {

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
    CarSe2(model_, s)->setXY(coord[0], coord[1]);
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
                   "' (expected one of: " + JoinNames(ControlPlannerNames()) + ")");
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

std::vector<std::string> ControlPlannerNames() {
  std::vector<std::string> names;
  for (ControlPlanner p :
       {ControlPlanner::kSyclopRrt, ControlPlanner::kSyclopEst, ControlPlanner::kRrt,
        ControlPlanner::kKpiece1, ControlPlanner::kEst, ControlPlanner::kPdst}) {
    names.push_back(ToString(p));
  }
  return names;
}

DecompositionKind ParseDecompositionKind(const std::string& name) {
  if (name == "acd") return DecompositionKind::kAcd;
  if (name == "grid") return DecompositionKind::kGrid;
  throw InputError("unknown decomposition '" + name + "' (expected one of: acd, grid)");
}

std::string ToString(DecompositionKind kind) {
  return kind == DecompositionKind::kAcd ? "acd" : "grid";
}

CarResult PlanCar(const CarQuery& query) {
  const Stopwatch stopwatch;
  CarResult result;
  auto obstacles =
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(query.workspace));
  collision::CollisionWorldOptions world_options;
  world_options.mode = query.collision_mode;
  auto world =
      std::make_shared<const collision::CollisionWorld>(obstacles, query.robot, world_options);
  const envs::Robot robot = query.robot;
  const Eigen::AlignedBox2d box = query.workspace.bounds;
  // Counted atomically: OMPL may check states from several threads in principle.
  auto checks = std::make_shared<std::atomic<std::uint64_t>>(0);
  oc::SpaceInformationPtr si = MakeCarSpaceInformation(
      query.model, box,
      [world, robot, box, checks](const Eigen::Isometry2d& pose) {
        checks->fetch_add(1, std::memory_order_relaxed);
        return envs::InsideBounds(robot, box, pose) && world->IsValid(pose);
      },
      query.car);

  ob::ScopedState<> start(si), goal(si);
  for (ob::ScopedState<>* s : {&start, &goal}) {
    for (unsigned i = 0; i < si->getStateDimension(); ++i) (*s)[i] = 0.0;
  }
  CarSe2(query.model, start.get())->setXY(query.start.x(), query.start.y());
  CarSe2(query.model, start.get())->setYaw(query.start.z());
  CarSe2(query.model, goal.get())->setXY(query.goal.x(), query.goal.y());
  CarSe2(query.model, goal.get())->setYaw(query.goal.z());
  if (!si->isValid(start.get())) {
    throw InputError("PlanCar(): start: the robot is in collision or out of bounds there");
  }
  if (!si->isValid(goal.get())) {
    throw InputError("PlanCar(): goal: the robot is in collision or out of bounds there");
  }
  checks->store(0);
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
      options.tau = TauOfBounds(query.tau_diag, box);
      options.measure = query.measure;
      const CachedDecomposition cached = DecomposeFreeSpaceCached(query.workspace, options);
      result.decomposition_ms = cached.compute_ms;
      result.decomposition = *cached.decomposition;
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
  const ob::PlannerStatus status =
      query.termination_checks > 0
          ? planner->solve(ob::IterationTerminationCondition(query.termination_checks))
          : planner->solve(remaining);
  // Syclop (OMPL 1.5) returns EXACT_SOLUTION with an approximate path when time runs out: ask
  // the problem definition whether the solution is exact.
  result.solved = status == ob::PlannerStatus::EXACT_SOLUTION && pdef->hasExactSolution();
  result.time_s = stopwatch.Seconds();
  result.collision_checks = checks->load();
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  result.tree_states = data.numVertices();
  auto reals = [&si](const ob::State* state) {
    std::vector<double> q;
    si->getStateSpace()->copyToReals(q, state);
    return q;
  };
  if (const ob::PathPtr solution = pdef->getSolutionPath()) {
    auto* path = solution->as<oc::PathControl>();
    if (result.solved) {
      result.path_duration = path->length();
      for (const ob::State* state : path->getStates()) result.path.push_back(reals(state));
    }
    oc::PathControl fine(*path);
    fine.interpolate();
    for (const ob::State* state : fine.getStates()) {
      result.trajectory.push_back(reals(state));
      if (!decomposition) continue;
      const int region = decomposition->locateRegion(state);
      if (region >= 0 &&
          (result.visited_regions.empty() || result.visited_regions.back() != region)) {
        result.visited_regions.push_back(region);
      }
    }
  }
  return result;
}

}  // namespace acdplan::planning::control
