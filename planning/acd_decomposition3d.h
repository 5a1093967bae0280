#pragma once
// AcdDecomposition3d: the components of a 3D world's ACD as the regions of OMPL's
// control-planning Decomposition (issue 12 on the 3D decomposition of issue 11), for Syclop
// with robots that move in 3D (R^3 or SE(3) workspaces).

#include <ompl/control/planners/syclop/Decomposition.h>

#include <Eigen/Core>
#include <vector>

#include "envs/free_space_decomposition3d.h"

namespace acdplan::planning {

namespace internal {
class HullSampler3d;
}

/// An ompl::control::Decomposition (dimension 3) whose regions are the components of a
/// envs::FreeSpaceDecomposition3d, as AcdDecomposition is for a 2D ACD:
///
/// - region i = decomposition.components[i]; getRegionVolume(i) = its volume;
/// - getNeighbors(i): the components sharing an opening with i (envs::ComponentGraph);
/// - locateRegion(s): the component whose hull holds project(s) most deeply (the components'
///   bounding boxes first, then their half-spaces: only the few components whose box holds
///   the point are tested); -1 outside every hull;
/// - sampleFromRegion(i): uniform inside the component's convex hull (rejection from its
///   bounding box; the component itself is nearly convex, its hull is what the decomposition
///   keeps);
/// - project(s): the position (x, y, z) of an SE3StateSpace state, or the first three
///   coordinates of a RealVectorStateSpace of dimension >= 3;
/// - sampleFullState(): the state sampler's uniform state with its position set to coord.
class AcdDecomposition3d : public ompl::control::Decomposition {
 public:
  /// `bounds`: the workspace bounds (3 dimensions); `space`: the state space of the states.
  /// @throws std::invalid_argument if `decomposition` has no components or `space` is not SE3
  ///         or RealVector of dimension >= 3.
  AcdDecomposition3d(const envs::FreeSpaceDecomposition3d& decomposition,
                     const ompl::base::RealVectorBounds& bounds,
                     const ompl::base::StateSpace* space);
  ~AcdDecomposition3d() override;

  int getNumRegions() const override;
  double getRegionVolume(int rid) override;
  int locateRegion(const ompl::base::State* s) const override;
  void project(const ompl::base::State* s, std::vector<double>& coord) const override;
  void getNeighbors(int rid, std::vector<int>& neighbors) const override;
  void sampleFromRegion(int rid, ompl::RNG& rng, std::vector<double>& coord) const override;
  void sampleFullState(const ompl::base::StateSamplerPtr& sampler, const std::vector<double>& coord,
                       ompl::base::State* s) const override;

  /// The region holding workspace point `p` (see locateRegion()), or -1.
  int LocatePoint(const Eigen::Vector3d& p) const;

 private:
  envs::FreeSpaceDecomposition3d decomposition_;
  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<internal::HullSampler3d> samplers_;
  std::vector<std::vector<int>> neighbors_;
  bool se3_ = false;
};

}  // namespace acdplan::planning
