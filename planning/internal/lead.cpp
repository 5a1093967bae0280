#include "planning/internal/lead.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <stdexcept>

#include "acd/component_locator2d.h"

namespace acdplan::planning::internal {

int LocateComponent(const acd::Decomposition2d& decomposition, const Eigen::Vector2d& p) {
  if (decomposition.components.empty()) return -1;
  const acd::ComponentLocator2d locator(decomposition);
  const int located = locator.Locate(p);
  if (located >= 0) return located;
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < decomposition.components.size(); ++i) {
    const double d = (decomposition.components[i].centroid - p).squaredNorm();
    if (d < best_distance) best_distance = d, best = static_cast<int>(i);
  }
  return best;
}

Lead FindLead(const acd::Decomposition2d& decomposition, int from, int to, double robot_width,
              double narrow_penalty) {
  const int n = static_cast<int>(decomposition.components.size());
  if (from < 0 || from >= n || to < 0 || to >= n) {
    throw std::invalid_argument("FindLead(): component index out of range");
  }
  struct Edge {
    int to, opening;
    double cost;
  };
  std::vector<std::vector<Edge>> graph(n);
  for (size_t o = 0; o < decomposition.openings.size(); ++o) {
    const acd::Opening2d& opening = decomposition.openings[o];
    const int a = opening.component_a, b = opening.component_b;
    if (a < 0 || b < 0 || a >= n || b >= n) continue;
    const Eigen::Vector2d mid = 0.5 * (opening.a + opening.b);
    double cost = (decomposition.components[a].centroid - mid).norm() +
                  (mid - decomposition.components[b].centroid).norm();
    if ((opening.b - opening.a).norm() < robot_width) cost *= narrow_penalty;
    graph[a].push_back({b, static_cast<int>(o), cost});
    graph[b].push_back({a, static_cast<int>(o), cost});
  }
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> distance(n, inf);
  std::vector<int> parent(n, -1), via(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  distance[from] = 0;
  queue.push({0.0, from});
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > distance[u]) continue;
    if (u == to) break;
    for (const Edge& e : graph[u]) {
      const double candidate = d + e.cost;
      if (candidate < distance[e.to]) {
        distance[e.to] = candidate;
        parent[e.to] = u;
        via[e.to] = e.opening;
        queue.push({candidate, e.to});
      }
    }
  }
  Lead lead;
  if (!(distance[to] < inf)) {
    lead.components = from == to ? std::vector<int>{from} : std::vector<int>{from, to};
    lead.cost = from == to ? 0.0 : inf;
    return lead;
  }
  lead.cost = distance[to];
  for (int c = to; c != -1; c = parent[c]) {
    lead.components.push_back(c);
    if (via[c] >= 0) lead.openings.push_back(via[c]);
  }
  std::reverse(lead.components.begin(), lead.components.end());
  std::reverse(lead.openings.begin(), lead.openings.end());
  return lead;
}

LeadDistribution::LeadDistribution(const acd::Decomposition2d& decomposition,
                                   const AcdLeadQuery& query,
                                   const AcdSamplerOptions& sampler_options,
                                   const AcdLeadOptions& lead_options)
    : options_(sampler_options), lead_options_(lead_options) {
  CheckAcdSamplerOptions(sampler_options);
  if (decomposition.components.empty()) {
    throw std::invalid_argument("acd_lead: the decomposition has no components");
  }
  const int from = LocateComponent(decomposition, query.start);
  const int to = LocateComponent(decomposition, query.goal);
  lead_ = FindLead(decomposition, from, to, query.robot_width, lead_options.narrow_penalty);

  for (const acd::Component2d& component : decomposition.components) {
    components_.emplace_back(component);
  }
  openings_segments_ = decomposition.openings;
  for (const acd::Opening2d& opening : decomposition.openings) {
    const Eigen::Vector2d d = opening.b - opening.a;
    AcdTarget target;
    target.position = 0.5 * (opening.a + opening.b);
    target.sigma = sampler_options.opening_spread * d.norm();
    target.opening = true;
    target.across = std::atan2(d.y(), d.x()) + M_PI / 2;
    openings_.push_back(target);
  }

  // Level 0: the lead. Level 1: + the components adjacent to it and the openings to them.
  // Level 2: everything. Degenerate parts (no area, zero-length opening) are left out.
  auto usable_component = [&](int c) { return components_[c].area() > 0; };
  auto usable_opening = [&](int o) { return openings_[o].sigma > 0; };
  std::set<int> lead_components(lead_.components.begin(), lead_.components.end());
  for (int c : lead_.components) {
    if (usable_component(c)) levels_[0].push_back({c, false});
  }
  for (int o : lead_.openings) {
    if (usable_opening(o)) levels_[0].push_back({o, true});
  }
  levels_[1] = levels_[0];
  std::set<int> added;
  for (size_t o = 0; o < decomposition.openings.size(); ++o) {
    const acd::Opening2d& opening = decomposition.openings[o];
    const bool in_a = lead_components.count(opening.component_a) > 0;
    const bool in_b = lead_components.count(opening.component_b) > 0;
    if (!in_a && !in_b) continue;
    const int oi = static_cast<int>(o);
    if (std::find(lead_.openings.begin(), lead_.openings.end(), oi) == lead_.openings.end() &&
        usable_opening(oi)) {
      levels_[1].push_back({oi, true});
    }
    const int other = in_a ? opening.component_b : opening.component_a;
    if (!lead_components.count(other) && added.insert(other).second && usable_component(other)) {
      levels_[1].push_back({other, false});
    }
  }
  for (size_t c = 0; c < components_.size(); ++c) {
    if (usable_component(static_cast<int>(c))) levels_[2].push_back({static_cast<int>(c), false});
  }
  for (size_t o = 0; o < openings_.size(); ++o) {
    if (usable_opening(static_cast<int>(o))) levels_[2].push_back({static_cast<int>(o), true});
  }
  // Weights: `opening_share` of the targeted draws spread evenly over the level's openings,
  // the rest over its components by their length along the lead -- the straight distance from
  // entry to exit (start, goal or opening midpoints; a nearly convex component holds that
  // segment), at least half sqrt(area), for a lead component; sqrt(area) for the others -- so
  // samples are spaced about evenly along the way, whether a component is a long thin
  // corridor or a wide room the lead only cuts across.
  std::vector<double> length(components_.size());
  for (size_t c = 0; c < components_.size(); ++c) length[c] = std::sqrt(components_[c].area());
  for (size_t i = 0; i < lead_.components.size(); ++i) {
    const int c = lead_.components[i];
    auto mid = [&](int o) { return openings_[o].position; };
    const Eigen::Vector2d in = i == 0 ? query.start : mid(lead_.openings[i - 1]);
    const Eigen::Vector2d out =
        i + 1 == lead_.components.size() ? query.goal : mid(lead_.openings[i]);
    length[c] = std::max((in - out).norm(), 0.5 * length[c]);
  }
  for (int level = 0; level < 3; ++level) {
    double total = 0;
    int openings = 0;
    for (const Part& part : levels_[level]) {
      if (part.opening) {
        ++openings;
      } else {
        total += length[part.index];
      }
    }
    const double share = openings == 0 ? 0.0 : total > 0 ? lead_options.opening_share : 1.0;
    double sum = 0;
    for (const Part& part : levels_[level]) {
      sum += part.opening ? share / openings : (1 - share) * length[part.index] / total;
      cumulative_[level].push_back(sum);
    }
  }
  const std::uint64_t parts = levels_[0].size();
  stage_ = std::max<std::uint64_t>(
      static_cast<std::uint64_t>(std::max(1, lead_options.min_stage_draws)),
      static_cast<std::uint64_t>(std::max(1, lead_options.stage_draws_per_part)) * parts);
}

int LeadDistribution::LevelAfter(std::uint64_t draws) const {
  if (draws < stage_) return 0;
  if (draws < 3 * stage_) return 1;
  return 2;
}

AcdDraw LeadDistribution::Draw(RandomEngine& rng, int level, double pick_u, int* part) const {
  level = std::min(std::max(level, 0), 2);
  const std::vector<Part>& parts = levels_[level];
  const double uniform_share =
      level < 2 ? lead_options_.lead_uniform_share : options_.uniform_share;
  if (parts.empty() || UniformReal(rng, 0.0, 1.0) < uniform_share) return AcdDraw{};
  const std::vector<double>& cumulative = cumulative_[level];
  const double u = std::min(std::max(pick_u, 0.0), 1.0) * cumulative.back();
  const size_t pick = std::min<size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin(),
      parts.size() - 1);
  const Part& chosen = parts[pick];
  AcdDraw draw;
  draw.uniform = false;
  if (!chosen.opening) {
    draw.position = components_[chosen.index].Sample(rng);
    if (part) *part = chosen.index;
    return draw;
  }
  // Across the opening, not around it: a uniform point of the segment's middle part, pushed
  // off it by a small Gaussian. In a convex component the segments of its two openings see
  // each other, so such points connect from opening to opening along the lead.
  const AcdTarget& target = openings_[chosen.index];
  const acd::Opening2d& opening = openings_segments_[chosen.index];
  const Eigen::Vector2d along = opening.b - opening.a;
  const Eigen::Vector2d normal = Eigen::Vector2d(-along.y(), along.x());
  const double t = UniformReal(rng, 0.1, 0.9);
  draw.position =
      opening.a + t * along + lead_options_.opening_jitter * StandardNormal(rng) * normal;
  if (options_.orientation == AcdOrientation::kAligned) {
    // The robot's long axis across the opening, either way round (as AcdTargets).
    draw.has_yaw = true;
    const double flip = UniformIndex(rng, 2) ? M_PI : 0.0;
    const double yaw =
        target.across - options_.long_axis + flip + options_.aligned_jitter * StandardNormal(rng);
    draw.yaw = std::remainder(yaw, 2 * M_PI);
  }
  if (part) *part = -1 - chosen.index;
  return draw;
}

std::vector<int> LeadDistribution::ComponentsAt(int level) const {
  std::vector<int> out;
  for (const Part& p : levels_[std::min(std::max(level, 0), 2)]) {
    if (!p.opening) out.push_back(p.index);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace acdplan::planning::internal
