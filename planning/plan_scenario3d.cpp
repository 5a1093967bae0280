#include "planning/plan_scenario3d.h"

#include <ompl/base/Planner.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include "base/input_error.h"
#include "base/stopwatch.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/acd_lead_sampler3d.h"
#include "planning/acd_prm.h"
#include "planning/acd_samplers3d.h"
#include "planning/counting_validity_checker.h"
#include "planning/internal/run_on_time_limit.h"
#include "planning/internal/scenario_setup.h"
#include "planning/internal/space_access.h"
#include "planning/internal/space_access3d.h"
#include "planning/registry.h"
#include "planning/sample_budget_roadmap.h"
#include "planning/tau_diag.h"

namespace acdplan::planning {

namespace ob = ompl::base;

Eigen::Isometry3d PoseFromXyzRpy(const std::vector<double>& q) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(q.at(0), q.at(1), q.at(2));
  if (q.size() >= 6) {
    pose.linear() = (Eigen::AngleAxisd(q[5], Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(q[4], Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(q[3], Eigen::Vector3d::UnitX()))
                        .toRotationMatrix();
  }
  return pose;
}

Eigen::Isometry3d PoseOfReals(const std::vector<double>& reals) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(reals.at(0), reals.at(1), reals.at(2));
  if (reals.size() >= 7) {
    pose.linear() =
        Eigen::Quaterniond(reals[6], reals[3], reals[4], reals[5]).normalized().toRotationMatrix();
  }
  return pose;
}

namespace {

void SetState(bool se3, const std::vector<double>& q, ob::State* state) {
  const Eigen::Isometry3d pose = PoseFromXyzRpy(q);
  if (se3) {
    auto* s = state->as<ob::SE3StateSpace::StateType>();
    s->setXYZ(q[0], q[1], q[2]);
    const Eigen::Quaterniond r(pose.linear());
    s->rotation().w = r.w(), s->rotation().x = r.x(), s->rotation().y = r.y(),
    s->rotation().z = r.z();
  } else {
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    for (int i = 0; i < 3; ++i) v[i] = q[static_cast<size_t>(i)];
  }
}

}  // namespace

PlanResult PlanScenario3d(const Scenario& scenario) {
  CheckScenario(scenario);
  const Stopwatch stopwatch;
  const std::string where = scenario.path.empty() ? "scenario" : scenario.path;
  PlanResult result;
  result.sampler = scenario.sampler;
  result.planner = scenario.planner;
  result.budget = internal::BudgetLabel(scenario);
  const envs::Workspace3d& workspace = scenario.workspace3d;

  // The free space's 3D ACD (cached on disk; decomposed for every sampler, as in 2D, so that
  // time_s compares like with like).
  envs::FreeSpaceDecomposition3dOptions acd_options;
  acd_options.tau = TauOfBounds(scenario.tau_diag, workspace.bounds);
  auto decomposition = std::make_shared<const envs::FreeSpaceDecomposition3d>(
      envs::DecomposeFreeSpace3d(workspace, acd_options));
  result.decomposition3d = decomposition;
  result.notes = decomposition->notes;
  result.decomposition_ms = stopwatch.Milliseconds();
  result.decomposition_compute_ms = decomposition->compute_ms;
  result.components = static_cast<int>(decomposition->components.size());
  result.openings = static_cast<int>(decomposition->openings.size());

  // Collision world and the state space.
  const auto world = internal::MakeCollisionWorld(workspace, scenario);
  const bool se3 = scenario.robot.shape == envs::RobotShape::kMesh;
  const internal::SpaceKind kind =
      se3 ? internal::SpaceKind::kSE3 : internal::SpaceKind::kRealVector3;
  const internal::CheckedSpace checked = internal::MakeCheckedSpace(
      workspace.bounds.min(), workspace.bounds.max(), se3, [world, kind](const ob::State* state) {
        return world->IsValid(internal::Pose3d(kind, state));
      });
  const std::shared_ptr<ob::SpaceInformation>& si = checked.si;
  const std::shared_ptr<CountingValidityChecker>& checker = checked.checker;

  ob::ScopedState<> start(si), goal(si);
  SetState(se3, scenario.start, start.get());
  SetState(se3, scenario.goal, goal.get());
  internal::CheckEndpoints(checked, start.get(), goal.get(), where);

  AcdSamplerOptions sampler_options = scenario.sampler_options;
  sampler_options.seed = scenario.seed;
  const acd::TriangleMesh* robot_mesh = se3 ? &scenario.robot.mesh : nullptr;
  if (scenario.sampler == SamplerType::kAcd) {
    InstallAcdSamplers3d(si, *decomposition, sampler_options, robot_mesh);
  } else if (scenario.sampler == SamplerType::kAcdLead) {
    // The lead through the 3D ACD's adjacency graph (acd_lead_sampler3d.h).
    AcdLeadQuery3d query;
    query.start = PoseFromXyzRpy(scenario.start).translation();
    query.goal = PoseFromXyzRpy(scenario.goal).translation();
    // In 3D a passage is a far smaller part of its rooms than in 2D, and a rigid body's pose
    // through it far narrower: 80% of the lead's draws at its openings (the window wall of
    // tests/planning/acd_lead3d_test.cpp: 8 of 10 seeds at 0.5, 10 of 10 at 0.85).
    AcdLeadOptions lead_options;
    lead_options.opening_share = kLeadOpeningShare3d;
    InstallAcdLeadSamplers3d(si, *decomposition, query, sampler_options, lead_options, robot_mesh);
  } else {
    InstallSampler(scenario.sampler, si, acd::Decomposition2d{}, sampler_options);
  }

  if (scenario.samples > 0) {
    SampleBudgetOptions options;
    options.samples = scenario.samples;
    options.star = scenario.planner == PlannerType::kPrmStar;
    if (scenario.planner == PlannerType::kPrmAcd) {
      options.acd_connections_3d = decomposition;
      options.seed = scenario.seed;
    }
    internal::RunSampleBudget(si, start.get(), goal.get(), options, &result);
  } else {
    ob::PlannerPtr planner =
        scenario.planner == PlannerType::kPrmAcd
            ? std::make_shared<AcdPrm>(si, decomposition, /*star=*/false, scenario.seed)
            : MakePlanner(scenario.planner, si, nullptr, scenario.seed);
    internal::RunOnTimeLimit(planner, start, goal, scenario.time_limit, &result);
  }
  result.collision_checks = checker->checks();
  result.time_s = stopwatch.Seconds();
  return result;
}

}  // namespace acdplan::planning
