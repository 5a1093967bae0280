#include "planning/internal/space_access3d.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <stdexcept>

namespace acdplan::planning::internal {

SpaceKind Classify3d(const ompl::base::StateSpace* space, const std::string& user) {
  const SpaceKind kind = Classify(space);
  if (kind != SpaceKind::kRealVector3 && kind != SpaceKind::kSE3) {
    throw std::invalid_argument(user + ": unsupported state space '" + space->getName() +
                                "' (supported: RealVectorStateSpace of dimension 3, "
                                "SE3StateSpace)");
  }
  return kind;
}

namespace ob = ompl::base;

bool SetFromDraw3d(SpaceKind kind, const ob::StateSpace* space, const AcdDraw3d& draw,
                   ob::State* state, RandomEngine& rng) {
  const bool se3 = kind == SpaceKind::kSE3;
  const ob::RealVectorBounds& bounds = se3 ? space->as<ob::SE3StateSpace>()->getBounds()
                                           : space->as<ob::RealVectorStateSpace>()->getBounds();
  for (int i = 0; i < 3; ++i) {
    if (!(draw.position[i] >= bounds.low[i] && draw.position[i] <= bounds.high[i])) return false;
  }
  if (!se3) {
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    for (int i = 0; i < 3; ++i) v[i] = draw.position[i];
    return true;
  }
  auto* s = state->as<ob::SE3StateSpace::StateType>();
  s->setXYZ(draw.position.x(), draw.position.y(), draw.position.z());
  const Eigen::Quaterniond q =
      (draw.has_rotation ? draw.rotation : UniformRotation(rng)).normalized();
  auto& r = s->rotation();
  r.w = q.w(), r.x = q.x(), r.y = q.y(), r.z = q.z();
  return true;
}

Eigen::Vector3d Position3d(SpaceKind kind, const ob::State* state) {
  if (kind == SpaceKind::kSE3) {
    const auto* s = state->as<ob::SE3StateSpace::StateType>();
    return Eigen::Vector3d(s->getX(), s->getY(), s->getZ());
  }
  const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Isometry3d Pose3d(SpaceKind kind, const ob::State* state) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Position3d(kind, state);
  if (kind == SpaceKind::kSE3) {
    const auto& r = state->as<ob::SE3StateSpace::StateType>()->rotation();
    pose.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  }
  return pose;
}

}  // namespace acdplan::planning::internal
