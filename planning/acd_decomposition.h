#pragma once
// AcdDecomposition: the components of a 2D ACD as the regions of OMPL's control-planning
// Decomposition, the workspace map Syclop (SyclopRRT, SyclopEST) searches its lead in.

#include <ompl/control/planners/syclop/Decomposition.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "acd/decomposition2d.h"

namespace acdplan::acd {
class ComponentLocator2d;
}

namespace acdplan::planning {

namespace internal {
class ComponentSampler;
}

/// An ompl::control::Decomposition (dimension 2) whose regions are the components of an
/// approximate convex decomposition of the free space (dissertation Ch. III; Syclop: Plaku,
/// Kavraki and Vardi, IEEE T-RO 2010). Compared with OMPL's GridDecomposition it has few
/// regions, each nearly convex and obstacle-free, adjacent only through real openings -- the
/// decomposition Syclop's lead search wants; OMPL's TriangularDecomposition needs the Triangle
/// library, which Debian's OMPL is built without.
///
/// - region i = decomposition.components[i]; getRegionVolume(i) = its area;
/// - getNeighbors(i): the components sharing an opening with i (acd::ComponentGraph);
/// - locateRegion(s): exact point location of project(s) (acd::ComponentLocator2d: a grid over
///   the components' boxes, O(1) per query on ordinary maps); -1 in an obstacle;
/// - sampleFromRegion(i): uniform inside the component polygon (uniform in its hull by area-
///   weighted triangles, rejected outside the polygon), not merely in its hull;
/// - project(s): the workspace (x, y) of the state: the first two coordinates of a
///   RealVectorStateSpace, the position of an SE2StateSpace, or of the SE2 first subspace of a
///   compound space (OMPL.app's kinematic car is SE(2), its dynamic car SE(2) x R^2);
/// - sampleFullState(): the state sampler's uniform state with its (x, y) set to the coordinate.
///
/// Thread safety: every const member is safe to call concurrently; getRegionVolume() (not
/// const in OMPL's interface) only reads.
class AcdDecomposition : public ompl::control::Decomposition {
 public:
  /// `bounds`: the workspace's (x, y) bounds (2 dimensions). `space`: the state space the
  /// states come from (for project()).
  /// @throws std::invalid_argument if `decomposition` has no components or `space` has no
  ///         (x, y) that project() knows.
  AcdDecomposition(const acd::Decomposition2d& decomposition,
                   const ompl::base::RealVectorBounds& bounds, const ompl::base::StateSpace* space);
  ~AcdDecomposition() override;

  int getNumRegions() const override;
  double getRegionVolume(int rid) override;
  int locateRegion(const ompl::base::State* s) const override;
  void project(const ompl::base::State* s, std::vector<double>& coord) const override;
  void getNeighbors(int rid, std::vector<int>& neighbors) const override;
  void sampleFromRegion(int rid, ompl::RNG& rng, std::vector<double>& coord) const override;
  void sampleFullState(const ompl::base::StateSamplerPtr& sampler, const std::vector<double>& coord,
                       ompl::base::State* s) const override;

  /// The region holding workspace point `p`, or -1.
  int LocatePoint(const Eigen::Vector2d& p) const;
  /// The decomposition the regions are the components of.
  const acd::Decomposition2d& decomposition() const { return decomposition_; }

 private:
  enum class Access { kRealVector, kSE2, kCompoundSE2 };

  acd::Decomposition2d decomposition_;
  std::unique_ptr<acd::ComponentLocator2d> locator_;
  std::vector<internal::ComponentSampler> samplers_;
  std::vector<std::vector<int>> neighbors_;
  std::vector<double> areas_;
  Access access_ = Access::kRealVector;
};

}  // namespace acdplan::planning
