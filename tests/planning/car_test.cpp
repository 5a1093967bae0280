// The cars of planning/control/car.h (OMPL.app's kinematic and second-order car ODEs through
// OMPL's ODE solver) and PlanCar()'s input checks. No planner runs on a clock here.

#include "planning/control/car.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <cmath>

#include "base/input_error.h"
#include "envs/generators.h"
#include "planning/control/plan_car.h"

namespace acdplan::planning::control {
namespace {

namespace ob = ompl::base;
namespace oc = ompl::control;

const Eigen::AlignedBox2d kBox(Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, 10));

/// Propagates `model` from the origin (heading 0, at rest) under `u` for `steps` steps.
std::vector<double> Drive(CarModel model, double u0, double u1, unsigned steps) {
  CarOptions options;
  options.length = 0.5;
  const oc::SpaceInformationPtr si = MakeCarSpaceInformation(
      model, kBox, [](const Eigen::Isometry2d&) { return true; }, options);
  ob::State* from = si->allocState();
  ob::State* to = si->allocState();
  std::vector<double> zero(si->getStateDimension(), 0.0);
  si->getStateSpace()->copyFromReals(from, zero);
  oc::Control* control = si->allocControl();
  double* u = control->as<oc::RealVectorControlSpace::ControlType>()->values;
  u[0] = u0, u[1] = u1;
  si->propagate(from, control, static_cast<int>(steps), to);
  std::vector<double> reals;
  si->getStateSpace()->copyToReals(reals, to);
  si->freeState(from), si->freeState(to), si->freeControl(control);
  return reals;
}

TEST(Car, KinematicCarDrivesStraightAndTurns) {
  // 20 steps of 0.05 s at v = 1: one unit along x.
  const std::vector<double> straight = Drive(CarModel::kKinematic, 1.0, 0.0, 20);
  EXPECT_NEAR(straight[0], 1.0, 1e-9);
  EXPECT_NEAR(straight[1], 0.0, 1e-12);
  EXPECT_NEAR(straight[2], 0.0, 1e-12);
  // Steering 0.3 rad: theta' = v tan(phi) / L = tan(0.3) / 0.5 for 1 s; left turn (y > 0).
  const std::vector<double> turn = Drive(CarModel::kKinematic, 1.0, 0.3, 20);
  EXPECT_NEAR(turn[2], std::tan(0.3) / 0.5, 1e-6);
  EXPECT_GT(turn[1], 0.0);
  // On the circle of radius L / tan(phi) about (0, R).
  const double radius = 0.5 / std::tan(0.3);
  EXPECT_NEAR(std::hypot(turn[0], turn[1] - radius), radius, 1e-6);
}

TEST(Car, DynamicCarAcceleratesAndSteersGradually) {
  // a = 0.5 for 1 s from rest: v = 0.5, x = a t^2 / 2 = 0.25; phi stays 0.
  const std::vector<double> q = Drive(CarModel::kDynamic, 0.5, 0.0, 20);
  ASSERT_EQ(q.size(), 5u);
  EXPECT_NEAR(q[3], 0.5, 1e-9);
  EXPECT_NEAR(q[0], 0.25, 1e-9);
  // Steering rate 0.03 rad/s for 1 s: phi = 0.03, at rest so no turn.
  const std::vector<double> s = Drive(CarModel::kDynamic, 0.0, 0.03, 20);
  EXPECT_NEAR(s[4], 0.03, 1e-9);
  EXPECT_NEAR(s[2], 0.0, 1e-12);
}

TEST(Car, NamesAndBadInput) {
  EXPECT_EQ(ParseCarModel("dynamic_car"), CarModel::kDynamic);
  EXPECT_EQ(ToString(CarModel::kKinematic), "kinematic_car");
  EXPECT_THROW(ParseCarModel("bicycle"), InputError);
  EXPECT_EQ(ParseControlPlanner("SyclopEST"), ControlPlanner::kSyclopEst);
  EXPECT_THROW(ParseControlPlanner("PRM"), InputError);
  CarOptions bad;
  bad.step = 0;
  EXPECT_THROW(MakeCarSpaceInformation(
                   CarModel::kKinematic, kBox, [](const Eigen::Isometry2d&) { return true; }, bad),
               InputError);
  CarQuery query;
  query.workspace = envs::GenerateWorkspace2d("bug_trap", 1, {0.4});
  query.robot = envs::Robot::Disc(0.1);
  query.start = Eigen::Vector3d(-100, 0, 0);  // Out of bounds.
  try {
    PlanCar(query);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("start"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace acdplan::planning::control
