#pragma once
// Control-space cars as OMPL.app defines them (KinematicCarPlanning, DynamicCarPlanning),
// integrated with OMPL's ODE solver.

#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/control/SpaceInformation.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <string>

namespace acdplan::planning::control {

/// Which car.
enum class CarModel {
  /// "kinematic_car": state SE(2) (x, y, theta); control (v, phi), v in [-1, 1] [units/s],
  /// steering phi in [-30, 30] deg; x' = v cos theta, y' = v sin theta, theta' = v tan(phi) / L.
  kKinematic,
  /// "dynamic_car" (second order): state SE(2) x R^2 (x, y, theta, v, phi), v in [-1, 1],
  /// phi in [-30, 30] deg; control (a, omega), a in [-0.5, 0.5] [units/s^2], omega in
  /// [-2, 2] deg/s; x' = v cos theta, y' = v sin theta, theta' = v m tan(phi) / L, v' = a,
  /// phi' = omega (OMPL.app's DynamicCarPlanning::ode, mass m = 1).
  kDynamic,
};

/// "kinematic_car" / "dynamic_car". @throws InputError for an unknown name.
/// (The bounds below are CarOptions' defaults, OMPL.app's.)
CarModel ParseCarModel(const std::string& name);
std::string ToString(CarModel model);

/// Options of MakeCarSpaceInformation(); `{}` is valid (OMPL.app's cars).
struct CarOptions {
  double length = 1.0;     ///< Car length L [units] (OMPL.app: 1 / lengthInv_ = 1); > 0.
  double max_speed = 1.0;  ///< |v| bound [units/s] (kinematic: control; dynamic: state); > 0.
  double max_steer = 30 * M_PI / 180;      ///< |phi| bound [rad] (OMPL.app: 30 deg); in (0, pi/2).
  double max_accel = 0.5;                  ///< kDynamic: |a| bound [units/s^2]; > 0.
  double max_steer_rate = 2 * M_PI / 180;  ///< kDynamic: |omega| bound [rad/s] (2 deg/s); > 0.
  double step = 0.05;               ///< Propagation step size [s] (ODE integration step); > 0.
  unsigned min_control_steps = 1;   ///< Shortest control duration [steps]; >= 1.
  unsigned max_control_steps = 20;  ///< Longest control duration [steps]; >= min.
};

/// Checks `options`. @throws InputError "MakeCarSpaceInformation(): <field>: <rule>, got <v>".
void CheckCarOptions(const CarOptions& options);

/// The control SpaceInformation of `model` over `xy_bounds`, its propagator OMPL's
/// ODEBasicSolver (RK4) on the car's ODE (theta wrapped to [-pi, pi] after each step), and
/// `valid(pose)` as the state validity checker (with the pose of (x, y, theta)). A default
/// (x, y) projection is registered on the state space for KPIECE1, EST and PDST.
ompl::control::SpaceInformationPtr MakeCarSpaceInformation(
    CarModel model, const Eigen::AlignedBox2d& xy_bounds,
    std::function<bool(const Eigen::Isometry2d& pose)> valid, const CarOptions& options = {});

/// The SE(2) part of a state of a car space: the state itself (kKinematic) or its first
/// component (kDynamic).
const ompl::base::SE2StateSpace::StateType* CarSe2(CarModel model, const ompl::base::State* state);
ompl::base::SE2StateSpace::StateType* CarSe2(CarModel model, ompl::base::State* state);

/// The pose (x, y, theta) of a state of a car space.
Eigen::Isometry2d CarPose(CarModel model, const ompl::base::State* state);

}  // namespace acdplan::planning::control
