#pragma once
// The lead in a 3D world (issue 12 on the 3D ACD of issue 11): the chain of 3D components from
// the start's to the goal's and the sampling distribution that follows it and widens (private
// to planning). The graph search and the levels are internal/lead.h's, shared with 2D.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "base/random.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/acd_lead_sampler.h"
#include "planning/acd_sampler_options.h"
#include "planning/internal/acd_targets3d.h"
#include "planning/internal/lead.h"

namespace acdplan::planning::internal {

/// The query a 3D lead is computed for.
struct LeadQuery3d {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< Reference point at the start [units].
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();   ///< Reference point at the goal [units].
  double robot_width = 0.0;  ///< RobotWidth3d(): openings narrower than this are penalised.
};

/// The smallest extent of a body across its principal axes [units] (a box's smallest side): a
/// lower bound on the narrowest square window it needs. 0 for fewer than 2 vertices.
double RobotWidth3d(const Eigen::Matrix<double, Eigen::Dynamic, 3>& vertices);

/// The component holding `p` (envs::FreeSpaceDecomposition3d::Locate(): the hull that holds it
/// most deeply), or, if none does, the one whose centroid is nearest; -1 only for an empty
/// decomposition.
int LocateComponent3d(const envs::FreeSpaceDecomposition3d& decomposition,
                      const Eigen::Vector3d& p);

/// ShortestLead() in the 3D adjacency graph: an opening joining a and b costs
/// |centroid(a) - opening centroid| + |opening centroid - centroid(b)|, times `narrow_penalty`
/// if its narrowest width is below `robot_width` or one of its components is thinner than that
/// (RobotWidth3d() of the component's hull: a sliver the robot cannot be in).
Lead FindLead3d(const envs::FreeSpaceDecomposition3d& decomposition, int from, int to,
                double robot_width, double narrow_penalty);

/// A point uniform inside a 3D component's hull (rejection from its bounding box against the
/// hull's half-spaces; the hull of a nearly convex piece, so a few draws land in the piece's
/// concavities and are rejected by the validity checker).
class HullSampler3d {
 public:
  static constexpr int kMaxRejections = 64;
  explicit HullSampler3d(const envs::FreeComponent3d& component);
  /// After kMaxRejections misses (a sliver hull), the centroid.
  Eigen::Vector3d Sample(RandomEngine& rng) const;
  /// As Sample(), drawing from `unit` (uniform in [0, 1); e.g. OMPL's RNG in a Decomposition).
  Eigen::Vector3d Sample(const std::function<double()>& unit) const;
  bool Contains(const Eigen::Vector3d& p) const;
  double volume() const { return volume_; }

 private:
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes_;
  Eigen::AlignedBox3d box_;
  Eigen::Vector3d centroid_;
  double volume_ = 0.0;
};

/// The 3D lead distribution: LeadLevels over the 3D decomposition. A component draw is uniform
/// inside its hull (HullSampler3d). An opening draw is, half the time, uniform on the opening
/// polygon shrunk to 80% about its centroid (as the middle 80% of a 2D opening segment: the
/// way from one opening to the next), otherwise AcdTargets3d's Gaussian about the centroid
/// (sigma opening_spread x the robot's play in the plane: where a body that barely fits
/// passes); both pushed along the normal by a Gaussian of sigma opening_spread x max(width,
/// robot length) (a rod is drawn through the passage and just out of it), with the robot's
/// long axis along the normal (AcdTargets3d::AlignedRotation) when `aligned` and the robot has
/// one.
class LeadDistribution3d {
 public:
  LeadDistribution3d(const envs::FreeSpaceDecomposition3d& decomposition, const LeadQuery3d& query,
                     const AcdSamplerOptions& sampler_options, const AcdLeadOptions& lead_options,
                     const LongAxis3d& long_axis = {});

  const Lead& lead() const { return lead_; }
  int LevelAfter(std::uint64_t draws) const { return levels_.LevelAfter(draws); }
  std::uint64_t stage_draws() const { return levels_.stage_draws(); }
  std::vector<int> ComponentsAt(int level) const { return levels_.ComponentsAt(level); }

  /// As LeadDistribution::Draw(): a draw at `level`, or "uniform" (lead_uniform_share at
  /// levels 0 and 1, uniform_share at level 2); `pick_u` picks the part; `part` receives the
  /// component index, or -1 - the opening index.
  AcdDraw3d Draw(RandomEngine& rng, int level, double pick_u, int* part = nullptr) const;

 private:
  struct OpeningShape {
    Eigen::Vector3d centroid, normal;
    std::vector<Eigen::Vector3d> fan;  ///< Triangle fan about the centroid: pairs of corners.
    std::vector<double> cumulative;    ///< Prefix sums of the fan triangles' areas.
    double sigma_normal = 0.0;
    double sigma_plane = 0.0;
  };

  AcdSamplerOptions options_;
  AcdLeadOptions lead_options_;
  AcdTargets3d targets_;  ///< For the aligned rotations.
  Lead lead_;
  LeadLevels levels_;
  std::vector<HullSampler3d> components_;
  std::vector<OpeningShape> openings_;
};

}  // namespace acdplan::planning::internal
