#pragma once
// PRM_ACD: OMPL's PRM with the roadmap connections of dissertation Algorithm 10.

#include <ompl/geometric/planners/prm/PRM.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "acd/component_locator2d.h"
#include "acd/decomposition2d.h"
#include "base/random.h"
#include "envs/free_space_decomposition3d.h"

namespace acdplan::planning {

/// OMPL's PRM whose new milestones are also connected across their ACD component and into the
/// adjacent ones (dissertation Ch. VI.C: with ACD "the connections between the samples can be
/// made more easily due to the nearly convex components").
///
/// Why: the ACD samplers put their samples in clusters around the components' centroids and
/// openings, and PRM's k nearest neighbours of a new milestone lie in its own cluster, so the
/// straight line to the cluster at the component's other opening -- free of obstacles, the
/// component being (nearly) convex -- is never tried. Besides PRM's neighbours (k = 10, or
/// PRM*'s rule with `star`), a milestone whose reference point (x, y) lies in component c is
/// offered up to `kPerComponent` milestones of c and of each component adjacent to c, picked at
/// random among those in roadmap components not yet offered, so each connection attempt can
/// join two parts of the roadmap. The motion validator still checks every edge.
///
/// Spaces: RealVector(2|3), SE2, SE3 (the x, y of the state locate it in a 2D decomposition;
/// x, y, z in a 3D one, envs::FreeSpaceDecomposition3d::Locate()). Seeded: the random picks
/// use their own generator.
class AcdPrm : public ompl::geometric::PRM {
 public:
  /// Members of a component tried per new milestone, its own and each adjacent one.
  static constexpr int kPerComponent = 2;

  AcdPrm(const ompl::base::SpaceInformationPtr& si, const acd::Decomposition2d& decomposition,
         bool star = false, std::uint64_t seed = 1);
  /// In a 3D world (RealVector(3) or SE3): components and adjacency of the free space's 3D ACD.
  AcdPrm(const ompl::base::SpaceInformationPtr& si,
         std::shared_ptr<const envs::FreeSpaceDecomposition3d> decomposition, bool star = false,
         std::uint64_t seed = 1);

  void setup() override;
  void clear() override;

  /// Index of the component whose polygon holds `xy` (exact, acd::ComponentLocator2d), or -1.
  int Locate(const Eigen::Vector2d& xy) const;

 private:
  /// PRM's neighbours of `v` plus the component neighbours described above.
  const std::vector<Vertex>& Connections(Vertex v);

  acd::ComponentLocator2d locator_;
  std::vector<std::vector<int>> adjacent_;
  std::vector<std::vector<Vertex>> members_;  ///< Milestones located in each component.
  ConnectionStrategy nearest_;                ///< PRM's own strategy.
  std::vector<Vertex> offered_;
  RandomEngine rng_;
  std::function<Eigen::Vector2d(const ompl::base::State*)> xy_;  ///< A state's reference point.
  /// The component of a state (-1: none): 2D by its reference point, 3D by its position.
  std::function<int(const ompl::base::State*)> locate_state_;
  std::shared_ptr<const envs::FreeSpaceDecomposition3d> decomposition3d_;
};

}  // namespace acdplan::planning
