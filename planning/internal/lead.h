#pragma once
// The lead: a chain of ACD components from the start's to the goal's, and the sampling
// distribution that follows it and widens (private to planning).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

/// An edge of the component adjacency graph: the opening joining components `a` and `b`.
struct LeadEdge {
  int a = -1, b = -1;  ///< Component indices (out of range: the edge is ignored).
  double cost = 0.0;   ///< Length of the way through the opening, narrowness penalty included.
  /// Its weight among a level's openings (LeadLevels): 1 in 2D (spread evenly), the
  /// narrowness in 3D; > 0.
  double weight = 1.0;
};

/// Dijkstra's shortest chain from `from` to `to` in the graph of `components` nodes whose
/// edge i is `openings[i]` (2D and 3D decompositions alike). Ties go to the lower index, so
/// the lead is deterministic. Unreachable: components {from, to}, no openings, cost infinity.
/// @throws std::invalid_argument if `from` or `to` is out of range.
Lead ShortestLead(int components, const std::vector<LeadEdge>& openings, int from, int to);

/// The component holding `p` (exact point location, acd::ComponentLocator2d), or, if none
/// does (a point on the free space's boundary), the one whose centroid is nearest; -1 only
/// for an empty decomposition.
/// The index of the component whose centroid is nearest `p` (the fallback of LocateComponent
/// and LocateComponent3d for a point in no component); -1 if there is none. 2D or 3D.
template <typename Components, typename Point>
int NearestCentroid(const Components& components, const Point& p) {
  int best = components.empty() ? -1 : 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < components.size(); ++i) {
    const double d = (components[i].centroid - p).squaredNorm();
    if (d < best_distance) best_distance = d, best = static_cast<int>(i);
  }
  return best;
}

/// The draw-th pick of a stratified sequence in [0, 1) (golden-ratio steps from `phase`): every
/// part of a lead gets its share of the draws with little variance, as Algorithm 10 gives each
/// target its k samples, where independent picks would leave some stretch of a long lead with
/// too few.
inline double StratifiedPick(double phase, std::uint64_t draw) {
  const double pick = phase + static_cast<double>(draw) * 0.6180339887498949;
  return pick - std::floor(pick);
}

int LocateComponent(const acd::Decomposition2d& decomposition, const Eigen::Vector2d& p);

/// ShortestLead() in the component adjacency graph. An opening joining a and b costs
/// |centroid(a) - mid| + |mid - centroid(b)|, times `narrow_penalty` if it is shorter than
/// `robot_width` (the robot cannot pass it, unless the cut is oblique to a wider passage:
/// penalised, not removed).
Lead FindLead(const acd::Decomposition2d& decomposition, int from, int to, double robot_width,
              double narrow_penalty);

/// A part of the lead distribution: a component or an opening.
struct LeadPart {
  int index;     ///< Component index, or opening index.
  bool opening;  ///< True for an opening.
};

/// The parts of the three levels of a lead distribution and their weights, and the widening
/// schedule (AcdLeadOptions), for a 2D or a 3D decomposition: level 0 the lead's components
/// and openings, level 1 adds the components adjacent to the lead and the openings to them,
/// level 2 every component and opening. Weights: `opening_share` of a level's draws spread
/// over its openings by their LeadEdge::weight, the rest over its components by
/// `component_length`.
class LeadLevels {
 public:
  LeadLevels() = default;
  /// `openings[i]` joins the components of opening i; unusable parts (no volume, a degenerate
  /// opening) are left out of every level.
  LeadLevels(const Lead& lead, const std::vector<LeadEdge>& openings,
             const std::vector<bool>& usable_component, const std::vector<bool>& usable_opening,
             const std::vector<double>& component_length, const AcdLeadOptions& options);

  /// 0 for the first `stage` draws, 1 for the next 2 x `stage`, 2 afterwards.
  int LevelAfter(std::uint64_t draws) const;
  std::uint64_t stage_draws() const { return stage_; }
  /// The part `pick_u` in [0, 1] falls on through the level's cumulative weights; null if the
  /// level has no parts.
  const LeadPart* Pick(int level, double pick_u) const;
  /// The components of `level` (sorted).
  std::vector<int> ComponentsAt(int level) const;

 private:
  std::vector<LeadPart> levels_[3];
  std::vector<double> cumulative_[3];  ///< Prefix sums of the parts' weights per level.
  std::uint64_t stage_ = 0;
};

/// The length of each lead component along the way -- the straight distance from its entry
/// to its exit (start, goal or the `opening_points` of the lead's openings; a nearly convex
/// component holds that segment), at least half its `size` -- and `size` for the others, so
/// that samples are spaced about evenly along the way whether a component is a long thin
/// corridor or a wide room the lead only cuts across. `size`: sqrt(area) in 2D, cbrt(volume)
/// in 3D.
template <class Point>
std::vector<double> LengthsAlongLead(const Lead& lead, std::vector<double> size, const Point& start,
                                     const Point& goal, const std::vector<Point>& opening_points) {
  for (size_t i = 0; i < lead.components.size(); ++i) {
    const int c = lead.components[i];
    const Point in = i == 0 ? start : opening_points[lead.openings[i - 1]];
    const Point out = i + 1 == lead.components.size() ? goal : opening_points[lead.openings[i]];
    size[c] = std::max((in - out).norm(), 0.5 * size[c]);
  }
  return size;
}

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
  int LevelAfter(std::uint64_t draws) const { return levels_.LevelAfter(draws); }
  /// Draws at the first level change (`stage` above).
  std::uint64_t stage_draws() const { return levels_.stage_draws(); }

  /// A draw at `level` (or "uniform": AcdLeadOptions::lead_uniform_share at levels 0 and 1,
  /// AcdSamplerOptions::uniform_share at level 2). `pick_u` in [0, 1] picks the part through
  /// the cumulative weights (the caller's stratified sequence); the rest comes from `rng`.
  /// `part` (if not null) receives the component index of a component draw, or -1 - opening
  /// index for an opening draw (< 0), unchanged for a uniform draw.
  AcdDraw Draw(RandomEngine& rng, int level, double pick_u, int* part = nullptr) const;

  /// The components of `level` (sorted).
  std::vector<int> ComponentsAt(int level) const { return levels_.ComponentsAt(level); }

 private:
  AcdSamplerOptions options_;
  AcdLeadOptions lead_options_;
  Lead lead_;
  LeadLevels levels_;
  std::vector<acd::Opening2d> openings_segments_;
  std::vector<ComponentSampler> components_;
  std::vector<AcdTarget> openings_;  ///< One per opening (position, sigma, across).
};

}  // namespace acdplan::planning::internal
