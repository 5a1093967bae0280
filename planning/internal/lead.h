#pragma once
// The lead: a chain of ACD components from the start's to the goal's, and the sampling
// distribution that follows it and widens (private to planning).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "acd/decomposition2d.h"
#include "base/random.h"
#include "planning/acd_lead_sampler.h"
#include "planning/acd_sampler_options.h"
#include "planning/internal/acd_targets.h"
#include "planning/internal/component_sampler.h"

namespace acdplan::planning::internal {

/// A chain of components joined by openings.
struct Lead {
  std::vector<int> components;  ///< From the start's component to the goal's.
  std::vector<int> openings;    ///< openings[i] joins components[i] and components[i + 1].
  double cost = 0.0;            ///< Sum of the edge costs; infinity if the goal is unreachable.
};

/// The component holding `p` (exact point location, acd::ComponentLocator2d), or, if none
/// does (a point on the free space's boundary), the one whose centroid is nearest; -1 only
/// for an empty decomposition.
int LocateComponent(const acd::Decomposition2d& decomposition, const Eigen::Vector2d& p);

/// Dijkstra's shortest chain from `from` to `to` in the component adjacency graph. An
/// opening joining a and b costs |centroid(a) - mid| + |mid - centroid(b)|, times
/// `narrow_penalty` if it is shorter than `robot_width` (the robot cannot pass it, unless the
/// cut is oblique to a wider passage: penalised, not removed). Ties go to the lower index, so
/// the lead is deterministic. Unreachable: components {from, to}, no openings, cost infinity.
Lead FindLead(const acd::Decomposition2d& decomposition, int from, int to, double robot_width,
              double narrow_penalty);

/// The lead-guided distribution of the reference point. Three levels, each a set of parts
/// drawn by weight (AcdLeadOptions::opening_share of the draws spread evenly over the openings,
/// the rest over the components by their length along the way): level 0 the
/// lead's components (uniform inside, internal::ComponentSampler) and openings (uniform along
/// the middle 80% of the segment, Gaussian across it with sigma opening_jitter x length,
/// robot turned across it when `aligned`); level 1 adds the
/// components adjacent to the lead and the openings to them; level 2 is every component and
/// opening. Plus a share of uniform draws at every level (see Draw()).
class LeadDistribution {
 public:
  LeadDistribution(const acd::Decomposition2d& decomposition, const AcdLeadQuery& query,
                   const AcdSamplerOptions& sampler_options, const AcdLeadOptions& lead_options);

  const Lead& lead() const { return lead_; }
  const AcdSamplerOptions& options() const { return options_; }

  /// The level in force after `draws` draws (AcdLeadOptions' schedule): 0 for the first
  /// `stage` draws, 1 for the next 2 x `stage`, 2 afterwards.
  int LevelAfter(std::uint64_t draws) const;
  /// Draws at the first level change (`stage` above).
  std::uint64_t stage_draws() const { return stage_; }

  /// A draw at `level` (or "uniform": AcdLeadOptions::lead_uniform_share at levels 0 and 1,
  /// AcdSamplerOptions::uniform_share at level 2). `pick_u` in [0, 1] picks the part through
  /// the cumulative weights (the caller's stratified sequence); the rest comes from `rng`.
  /// `part` (if not null) receives the component index of a component draw, or -1 - opening
  /// index for an opening draw (< 0), unchanged for a uniform draw.
  AcdDraw Draw(RandomEngine& rng, int level, double pick_u, int* part = nullptr) const;

  /// The components of `level` (sorted).
  std::vector<int> ComponentsAt(int level) const;

 private:
  struct Part {
    int index;     ///< Component index, or opening index.
    bool opening;  ///< True for an opening.
  };

  AcdSamplerOptions options_;
  AcdLeadOptions lead_options_;
  Lead lead_;
  std::vector<acd::Opening2d> openings_segments_;
  std::vector<double> cumulative_[3];  ///< Prefix sums of the parts' weights per level.
  std::vector<ComponentSampler> components_;
  std::vector<AcdTarget> openings_;  ///< One per opening (position, sigma, across).
  std::vector<Part> levels_[3];
  std::uint64_t stage_ = 0;
};

}  // namespace acdplan::planning::internal
