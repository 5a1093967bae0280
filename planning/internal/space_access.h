#pragma once
// Reading and writing the states of the spaces the ACD samplers support (private to planning).

#include <ompl/base/StateSpace.h>

#include <Eigen/Core>

#include "base/random.h"
#include "planning/internal/acd_targets.h"

namespace acdplan::planning::internal {

/// The state spaces the samplers support.
enum class SpaceKind { kRealVector2, kRealVector3, kSE2, kSE3 };

/// The kind of `space`. @throws std::invalid_argument naming the space otherwise.
SpaceKind Classify(const ompl::base::StateSpace* space);

/// Uniform over the space's bounds (uniform yaw / uniform rotation).
void SampleUniform(SpaceKind kind, const ompl::base::StateSpace* space, ompl::base::State* state,
                   RandomEngine& rng);

/// Writes `draw` (a target-based draw) into `state`: x, y from the draw; z (3D) uniform over
/// the bounds; the yaw from the draw if it has one, else uniform; SE(3) rotations uniform (or
/// a rotation about z by the draw's yaw). @returns false if x, y fall outside the bounds.
bool SetFromDraw(SpaceKind kind, const ompl::base::StateSpace* space, const AcdDraw& draw,
                 ompl::base::State* state, RandomEngine& rng);

/// Sets only x, y of `state`. @returns false (and changes nothing) outside the bounds.
bool SetXy(SpaceKind kind, const ompl::base::StateSpace* space, ompl::base::State* state,
           const Eigen::Vector2d& xy);

/// The (x, y) of `state`.
Eigen::Vector2d Xy(SpaceKind kind, const ompl::base::State* state);

/// Uniform in the box of half-side `distance` around `near` (angles within `distance` too),
/// clipped to the bounds.
void SampleUniformNear(SpaceKind kind, const ompl::base::StateSpace* space,
                       ompl::base::State* state, const ompl::base::State* near, double distance,
                       RandomEngine& rng);

/// Gaussian around `mean`, `stddev` per coordinate (rotation: random axis, Gaussian angle),
/// clipped to the bounds.
void SampleGaussian(SpaceKind kind, const ompl::base::StateSpace* space, ompl::base::State* state,
                    const ompl::base::State* mean, double stddev, RandomEngine& rng);

}  // namespace acdplan::planning::internal
