#include "planning/internal/space_access.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "planning/internal/acd_targets3d.h"

namespace acdplan::planning::internal {
namespace ob = ompl::base;

namespace {

const ob::RealVectorBounds& Bounds(SpaceKind kind, const ob::StateSpace* space) {
  switch (kind) {
    case SpaceKind::kRealVector2:
    case SpaceKind::kRealVector3:
      return space->as<ob::RealVectorStateSpace>()->getBounds();
    case SpaceKind::kSE2:
      return space->as<ob::SE2StateSpace>()->getBounds();
    case SpaceKind::kSE3:
      return space->as<ob::SE3StateSpace>()->getBounds();
  }
  throw std::logic_error("Bounds(): unknown space kind");
}

/// Pointers to the translation coordinates of `state` (2 or 3 of them).
int Coordinates(SpaceKind kind, ob::State* state, double* out[3]) {
  switch (kind) {
    case SpaceKind::kRealVector2:
    case SpaceKind::kRealVector3: {
      double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
      out[0] = v, out[1] = v + 1, out[2] = v + 2;
      return kind == SpaceKind::kRealVector2 ? 2 : 3;
    }
    case SpaceKind::kSE2: {
      auto* s = state->as<ob::SE2StateSpace::StateType>();
      double* v = s->as<ob::RealVectorStateSpace::StateType>(0)->values;
      out[0] = v, out[1] = v + 1;
      return 2;
    }
    case SpaceKind::kSE3: {
      auto* s = state->as<ob::SE3StateSpace::StateType>();
      double* v = s->as<ob::RealVectorStateSpace::StateType>(0)->values;
      out[0] = v, out[1] = v + 1, out[2] = v + 2;
      return 3;
    }
  }
  return 0;
}

double Clamp(double x, double low, double high) { return std::min(std::max(x, low), high); }

Eigen::Quaterniond GetRotation(const ob::State* state) {
  const auto& r = state->as<ob::SE3StateSpace::StateType>()->rotation();
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z);
}

void SetRotation(ob::State* state, const Eigen::Quaterniond& q_in) {
  const Eigen::Quaterniond q = q_in.normalized();
  auto& r = state->as<ob::SE3StateSpace::StateType>()->rotation();
  r.w = q.w(), r.x = q.x(), r.y = q.y(), r.z = q.z();
}

/// `base` turned by an angle (`angle_of(rng)`) about a random axis.
template <typename Angle>
Eigen::Quaterniond Perturbed(const Eigen::Quaterniond& base, RandomEngine& rng, Angle angle_of) {
  const double x = StandardNormal(rng), y = StandardNormal(rng), z = StandardNormal(rng);
  Eigen::Vector3d axis(x, y, z);
  if (axis.norm() < 1e-12) axis = Eigen::Vector3d::UnitZ();
  return base * Eigen::Quaterniond(Eigen::AngleAxisd(angle_of(rng), axis.normalized()));
}

}  // namespace

SpaceKind Classify(const ob::StateSpace* space) {
  switch (space->getType()) {
    case ob::STATE_SPACE_REAL_VECTOR:
      if (space->getDimension() == 2) return SpaceKind::kRealVector2;
      if (space->getDimension() == 3) return SpaceKind::kRealVector3;
      break;
    case ob::STATE_SPACE_SE2:
      return SpaceKind::kSE2;
    case ob::STATE_SPACE_SE3:
      return SpaceKind::kSE3;
    default:
      break;
  }
  throw std::invalid_argument("ACD samplers: unsupported state space '" + space->getName() +
                              "' (supported: RealVectorStateSpace of dimension 2 or 3, "
                              "SE2StateSpace, SE3StateSpace)");
}

void SampleUniform(SpaceKind kind, const ob::StateSpace* space, ob::State* state,
                   RandomEngine& rng) {
  const ob::RealVectorBounds& bounds = Bounds(kind, space);
  double* x[3] = {nullptr, nullptr, nullptr};
  const int n = Coordinates(kind, state, x);
  for (int i = 0; i < n; ++i) *x[i] = UniformReal(rng, bounds.low[i], bounds.high[i]);
  if (kind == SpaceKind::kSE2) {
    state->as<ob::SE2StateSpace::StateType>()->setYaw(UniformReal(rng, -M_PI, M_PI));
  } else if (kind == SpaceKind::kSE3) {
    SetRotation(state, UniformRotation(rng));
  }
}

bool SetFromDraw(SpaceKind kind, const ob::StateSpace* space, const AcdDraw& draw, ob::State* state,
                 RandomEngine& rng) {
  const ob::RealVectorBounds& bounds = Bounds(kind, space);
  for (int i = 0; i < 2; ++i) {
    if (draw.position[i] < bounds.low[i] || draw.position[i] > bounds.high[i]) return false;
  }
  double* x[3] = {nullptr, nullptr, nullptr};
  const int n = Coordinates(kind, state, x);
  *x[0] = draw.position.x();
  *x[1] = draw.position.y();
  // A 2D decomposition says nothing about z: uniform over the bounds (3D ACD targets later).
  if (n == 3) *x[2] = UniformReal(rng, bounds.low[2], bounds.high[2]);
  const double yaw = draw.has_yaw ? draw.yaw : UniformReal(rng, -M_PI, M_PI);
  if (kind == SpaceKind::kSE2) {
    state->as<ob::SE2StateSpace::StateType>()->setYaw(yaw);
  } else if (kind == SpaceKind::kSE3) {
    SetRotation(state, draw.has_yaw
                           ? Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))
                           : UniformRotation(rng));
  }
  return true;
}

bool SetXy(SpaceKind kind, const ob::StateSpace* space, ob::State* state,
           const Eigen::Vector2d& xy) {
  const ob::RealVectorBounds& bounds = Bounds(kind, space);
  for (int i = 0; i < 2; ++i) {
    if (xy[i] < bounds.low[i] || xy[i] > bounds.high[i]) return false;
  }
  double* x[3] = {nullptr, nullptr, nullptr};
  Coordinates(kind, state, x);
  *x[0] = xy.x();
  *x[1] = xy.y();
  return true;
}

Eigen::Vector2d Xy(SpaceKind kind, const ob::State* state) {
  double* x[3] = {nullptr, nullptr, nullptr};
  const int n = Coordinates(kind, const_cast<ob::State*>(state), x);
  (void)n;
  return Eigen::Vector2d(*x[0], *x[1]);
}

void SampleUniformNear(SpaceKind kind, const ob::StateSpace* space, ob::State* state,
                       const ob::State* near, double distance, RandomEngine& rng) {
  const ob::RealVectorBounds& bounds = Bounds(kind, space);
  double* x[3] = {nullptr, nullptr, nullptr};
  double* c[3] = {nullptr, nullptr, nullptr};
  const int n = Coordinates(kind, state, x);
  Coordinates(kind, const_cast<ob::State*>(near), c);
  for (int i = 0; i < n; ++i) {
    const double low = std::max(bounds.low[i], *c[i] - distance);
    const double high = std::min(bounds.high[i], *c[i] + distance);
    *x[i] = low < high ? UniformReal(rng, low, high) : Clamp(*c[i], bounds.low[i], bounds.high[i]);
  }
  if (kind == SpaceKind::kSE2) {
    const double yaw = near->as<ob::SE2StateSpace::StateType>()->getYaw() +
                       UniformReal(rng, -std::min(distance, M_PI), std::min(distance, M_PI));
    state->as<ob::SE2StateSpace::StateType>()->setYaw(std::remainder(yaw, 2 * M_PI));
  } else if (kind == SpaceKind::kSE3) {
    const double limit = std::min(distance, M_PI);
    SetRotation(state, Perturbed(GetRotation(near), rng, [limit](RandomEngine& g) {
                  return UniformReal(g, -limit, limit);
                }));
  }
}

void SampleGaussian(SpaceKind kind, const ob::StateSpace* space, ob::State* state,
                    const ob::State* mean, double stddev, RandomEngine& rng) {
  const ob::RealVectorBounds& bounds = Bounds(kind, space);
  auto gauss = [stddev](RandomEngine& g) { return stddev > 0 ? stddev * StandardNormal(g) : 0.0; };
  double* x[3] = {nullptr, nullptr, nullptr};
  double* c[3] = {nullptr, nullptr, nullptr};
  const int n = Coordinates(kind, state, x);
  Coordinates(kind, const_cast<ob::State*>(mean), c);
  for (int i = 0; i < n; ++i) *x[i] = Clamp(*c[i] + gauss(rng), bounds.low[i], bounds.high[i]);
  if (kind == SpaceKind::kSE2) {
    const double yaw = mean->as<ob::SE2StateSpace::StateType>()->getYaw() + gauss(rng);
    state->as<ob::SE2StateSpace::StateType>()->setYaw(std::remainder(yaw, 2 * M_PI));
  } else if (kind == SpaceKind::kSE3) {
    SetRotation(state, Perturbed(GetRotation(mean), rng, gauss));
  }
}

}  // namespace acdplan::planning::internal
