#pragma once
// Reading and writing positions and rotations of R^3 and SE(3) states (private to planning).

#include <ompl/base/StateSpace.h>

#include <Eigen/Geometry>
#include <string>

#include "base/random.h"
#include "planning/internal/acd_targets3d.h"
#include "planning/internal/space_access.h"

namespace acdplan::planning::internal {

/// Classify(space), which must be kRealVector3 or kSE3. @throws std::invalid_argument naming
/// `user` (e.g. "3D ACD samplers") and the space otherwise.
SpaceKind Classify3d(const ompl::base::StateSpace* space, const std::string& user);

/// Writes `draw` into `state` (kRealVector3 or kSE3): the position, and for SE(3) the draw's
/// rotation if it has one, else a uniform one. @returns false (state unspecified) if the
/// position is outside the space's bounds.
bool SetFromDraw3d(SpaceKind kind, const ompl::base::StateSpace* space, const AcdDraw3d& draw,
                   ompl::base::State* state, RandomEngine& rng);

/// The position of a kRealVector3 or kSE3 state.
Eigen::Vector3d Position3d(SpaceKind kind, const ompl::base::State* state);

/// The pose of a kRealVector3 (identity rotation) or kSE3 state.
Eigen::Isometry3d Pose3d(SpaceKind kind, const ompl::base::State* state);

}  // namespace acdplan::planning::internal
