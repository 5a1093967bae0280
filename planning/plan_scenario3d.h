#pragma once
// Runs a 3D Scenario: free space and its 3D ACD (cached), collision world, R^3 or SE(3), the
// sampler and the planner.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "planning/plan_scenario.h"
#include "planning/scenario.h"

namespace acdplan::planning {

/// Plans a 3D `scenario` (dimension 3): envs::DecomposeFreeSpace3d (tau = tau_diag x the bounds'
/// diagonal; the disk cache envs::FreeSpaceCacheDir(), so repeated runs decompose once), a
/// collision::CollisionWorld on the obstacle meshes, R^3 for a point robot or SE(3) for a mesh
/// robot (the reference point bounded by the world box, as OMPL.app does), the sampler -- acd:
/// InstallAcdSamplers3d() with the mesh's principal axis as the long axis when it has one --
/// and the planner (PRM_ACD connects across adjacent 3D components), on the sample budget or
/// the time limit as in 2D. The decomposition's notes (obstacles left out of the free space)
/// are in PlanResult::notes.
/// @throws InputError if the start or the goal is in collision or out of bounds.
PlanResult PlanScenario3d(const Scenario& scenario);

/// The SE(3) pose of [x, y, z, roll, pitch, yaw] (rotation Rz(yaw) Ry(pitch) Rx(roll)) or of
/// [x, y, z] (identity rotation).
Eigen::Isometry3d PoseFromXyzRpy(const std::vector<double>& q);

/// The pose of a path state of a 3D PlanResult: [x, y, z] or OMPL's SE3 reals [x, y, z, qx,
/// qy, qz, qw].
Eigen::Isometry3d PoseOfReals(const std::vector<double>& reals);

}  // namespace acdplan::planning
