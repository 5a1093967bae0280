#include "planning/control/car.h"

#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/control/ODESolver.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <cmath>

#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::planning::control {

namespace ob = ompl::base;
namespace oc = ompl::control;

namespace {

/// Projects a car state to its (x, y), cells 1/20 of the bounds (KPIECE1, EST, PDST).
class XyProjection : public ob::ProjectionEvaluator {
 public:
  XyProjection(const ob::StateSpace* space, CarModel model, const Eigen::AlignedBox2d& bounds)
      : ob::ProjectionEvaluator(space), model_(model), bounds_(bounds) {}
  unsigned int getDimension() const override { return 2; }
  void defaultCellSizes() override {
    cellSizes_ = {bounds_.sizes().x() / 20, bounds_.sizes().y() / 20};
  }
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> out) const override {
    const auto* s = CarSe2(model_, state);
    out[0] = s->getX();
    out[1] = s->getY();
  }

 private:
  CarModel model_;
  Eigen::AlignedBox2d bounds_;
};

}  // namespace

CarModel ParseCarModel(const std::string& name) {
  if (name == "kinematic_car") return CarModel::kKinematic;
  if (name == "dynamic_car") return CarModel::kDynamic;
  throw InputError("unknown car '" + name + "' (expected one of: kinematic_car, dynamic_car)");
}

std::string ToString(CarModel model) {
  return model == CarModel::kKinematic ? "kinematic_car" : "dynamic_car";
}

const ob::SE2StateSpace::StateType* CarSe2(CarModel model, const ob::State* state) {
  return model == CarModel::kKinematic
             ? state->as<ob::SE2StateSpace::StateType>()
             : state->as<ob::CompoundStateSpace::StateType>()->as<ob::SE2StateSpace::StateType>(0);
}

ob::SE2StateSpace::StateType* CarSe2(CarModel model, ob::State* state) {
  return const_cast<ob::SE2StateSpace::StateType*>(
      CarSe2(model, static_cast<const ob::State*>(state)));
}

Eigen::Isometry2d CarPose(CarModel model, const ob::State* state) {
  const auto* s = CarSe2(model, state);
  Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
  pose.translate(Eigen::Vector2d(s->getX(), s->getY()));
  pose.rotate(s->getYaw());
  return pose;
}

void CheckCarOptions(const CarOptions& o) {
  auto fail = [](const std::string& field, const std::string& rule, double value) {
    throw InputError("MakeCarSpaceInformation(): " + field + ": " + rule + ", got " +
                     FormatSignificant(value, 6));
  };
  if (!(o.length > 0)) fail("length", "expected > 0", o.length);
  if (!(o.max_speed > 0)) fail("max_speed", "expected > 0", o.max_speed);
  if (!(o.max_steer > 0 && o.max_steer < M_PI / 2)) {
    fail("max_steer", "expected in (0, pi/2) [rad]", o.max_steer);
  }
  if (!(o.max_accel > 0)) fail("max_accel", "expected > 0", o.max_accel);
  if (!(o.max_steer_rate > 0)) fail("max_steer_rate", "expected > 0", o.max_steer_rate);
  if (!(o.step > 0)) fail("step", "expected > 0", o.step);
  if (o.min_control_steps < 1) fail("min_control_steps", "expected >= 1", o.min_control_steps);
  if (o.max_control_steps < o.min_control_steps) {
    fail("max_control_steps", "expected >= min_control_steps", o.max_control_steps);
  }
}

oc::SpaceInformationPtr MakeCarSpaceInformation(CarModel model,
                                                const Eigen::AlignedBox2d& xy_bounds,
                                                std::function<bool(const Eigen::Isometry2d&)> valid,
                                                const CarOptions& options) {
  CheckCarOptions(options);
  ob::RealVectorBounds xy(2);
  for (int i = 0; i < 2; ++i) {
    xy.setLow(i, xy_bounds.min()[i]);
    xy.setHigh(i, xy_bounds.max()[i]);
  }
  auto se2 = std::make_shared<ob::SE2StateSpace>();
  se2->setBounds(xy);
  ob::StateSpacePtr space = se2;
  ob::RealVectorBounds controls(2);
  if (model == CarModel::kKinematic) {
    controls.setLow(0, -options.max_speed), controls.setHigh(0, options.max_speed);
    controls.setLow(1, -options.max_steer), controls.setHigh(1, options.max_steer);
  } else {
    auto velocity = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds vphi(2);
    vphi.setLow(0, -options.max_speed), vphi.setHigh(0, options.max_speed);
    vphi.setLow(1, -options.max_steer), vphi.setHigh(1, options.max_steer);
    velocity->setBounds(vphi);
    auto compound = std::make_shared<ob::CompoundStateSpace>();
    compound->addSubspace(se2, 1.0);
    compound->addSubspace(velocity, 0.3);
    compound->lock();
    space = compound;
    controls.setLow(0, -options.max_accel), controls.setHigh(0, options.max_accel);
    controls.setLow(1, -options.max_steer_rate), controls.setHigh(1, options.max_steer_rate);
  }
  auto control_space = std::make_shared<oc::RealVectorControlSpace>(space, 2);
  control_space->setBounds(controls);
  auto si = std::make_shared<oc::SpaceInformation>(space, control_space);

  const double inverse_length = 1.0 / options.length;
  oc::ODESolver::ODE ode;
  if (model == CarModel::kKinematic) {
    ode = [inverse_length](const oc::ODESolver::StateType& q, const oc::Control* control,
                           oc::ODESolver::StateType& qdot) {
      const double* u = control->as<oc::RealVectorControlSpace::ControlType>()->values;
      qdot.assign(q.size(), 0.0);
      qdot[0] = u[0] * std::cos(q[2]);
      qdot[1] = u[0] * std::sin(q[2]);
      qdot[2] = u[0] * inverse_length * std::tan(u[1]);
    };
  } else {
    ode = [inverse_length](const oc::ODESolver::StateType& q, const oc::Control* control,
                           oc::ODESolver::StateType& qdot) {
      const double* u = control->as<oc::RealVectorControlSpace::ControlType>()->values;
      const double mass = 1.0;
      qdot.assign(q.size(), 0.0);
      qdot[0] = q[3] * std::cos(q[2]);
      qdot[1] = q[3] * std::sin(q[2]);
      qdot[2] = q[3] * mass * inverse_length * std::tan(q[4]);
      qdot[3] = u[0];
      qdot[4] = u[1];
    };
  }
  // The solver sees `si` through a non-owning pointer: `si` owns the propagator, which owns the
  // solver, so an owning pointer back would be a reference cycle that leaks both.
  const oc::SpaceInformationPtr si_view(si.get(), [](oc::SpaceInformation*) {});
  auto solver = std::make_shared<oc::ODEBasicSolver<>>(si_view, ode, options.step);
  // After integrating: wrap theta and clamp (v, phi) into their bounds, as OMPL.app does.
  auto post = [model, space](const ob::State*, const oc::Control*, double, ob::State* result) {
    ob::SE2StateSpace::StateType* s =
        model == CarModel::kKinematic
            ? result->as<ob::SE2StateSpace::StateType>()
            : result->as<ob::CompoundStateSpace::StateType>()->as<ob::SE2StateSpace::StateType>(0);
    s->setYaw(std::remainder(s->getYaw(), 2 * M_PI));
    if (model == CarModel::kDynamic) {
      space->as<ob::CompoundStateSpace>()->getSubspace(1)->enforceBounds(
          result->as<ob::CompoundStateSpace::StateType>()->components[1]);
    }
  };
  si->setStatePropagator(oc::ODESolver::getStatePropagator(solver, post));
  si->setPropagationStepSize(options.step);
  si->setMinMaxControlDuration(options.min_control_steps, options.max_control_steps);
  si->setStateValidityChecker(
      [model, valid = std::move(valid), si_raw = si.get()](const ob::State* state) {
        return si_raw->satisfiesBounds(state) && valid(CarPose(model, state));
      });
  space->registerDefaultProjection(std::make_shared<XyProjection>(space.get(), model, xy_bounds));
  si->setup();
  return si;
}

}  // namespace acdplan::planning::control
