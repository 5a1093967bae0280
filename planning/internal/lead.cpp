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
  return NearestCentroid(decomposition.components, p);
}

Lead ShortestLead(int n, const std::vector<LeadEdge>& openings, int from, int to) {
  if (from < 0 || from >= n || to < 0 || to >= n) {
    throw std::invalid_argument("FindLead(): component index out of range");
  }
  struct Edge {
    int to, opening;
    double cost;
  };
  std::vector<std::vector<Edge>> graph(n);
  for (size_t o = 0; o < openings.size(); ++o) {
    const int a = openings[o].a, b = openings[o].b;
    if (a < 0 || b < 0 || a >= n || b >= n) continue;
    graph[a].push_back({b, static_cast<int>(o), openings[o].cost});
    graph[b].push_back({a, static_cast<int>(o), openings[o].cost});
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

Lead FindLead(const acd::Decomposition2d& decomposition, int from, int to, double robot_width,
              double narrow_penalty) {
  const int n = static_cast<int>(decomposition.components.size());
  std::vector<LeadEdge> edges;
  for (const acd::Opening2d& opening : decomposition.openings) {
    LeadEdge edge{opening.component_a, opening.component_b, 0.0};
    if (edge.a >= 0 && edge.b >= 0 && edge.a < n && edge.b < n) {
      const Eigen::Vector2d mid = 0.5 * (opening.a + opening.b);
      edge.cost = (decomposition.components[edge.a].centroid - mid).norm() +
                  (mid - decomposition.components[edge.b].centroid).norm();
      if ((opening.b - opening.a).norm() < robot_width) edge.cost *= narrow_penalty;
    }
    edges.push_back(edge);
  }
  return ShortestLead(n, edges, from, to);
}

LeadLevels::LeadLevels(const Lead& lead, const std::vector<LeadEdge>& openings,
                       const std::vector<bool>& usable_component,
                       const std::vector<bool>& usable_opening,
                       const std::vector<double>& component_length, const AcdLeadOptions& options) {
  std::set<int> lead_components(lead.components.begin(), lead.components.end());
  for (int c : lead.components) {
    if (usable_component[c]) levels_[0].push_back({c, false});
  }
  for (int o : lead.openings) {
    if (usable_opening[o]) levels_[0].push_back({o, true});
  }
  levels_[1] = levels_[0];
  std::set<int> added;
  for (size_t o = 0; o < openings.size(); ++o) {
    const bool in_a = lead_components.count(openings[o].a) > 0;
    const bool in_b = lead_components.count(openings[o].b) > 0;
    if (!in_a && !in_b) continue;
    const int oi = static_cast<int>(o);
    if (std::find(lead.openings.begin(), lead.openings.end(), oi) == lead.openings.end() &&
        usable_opening[o]) {
      levels_[1].push_back({oi, true});
    }
    const int other = in_a ? openings[o].b : openings[o].a;
    if (other >= 0 && other < static_cast<int>(usable_component.size()) &&
        !lead_components.count(other) && added.insert(other).second && usable_component[other]) {
      levels_[1].push_back({other, false});
    }
  }
  for (size_t c = 0; c < usable_component.size(); ++c) {
    if (usable_component[c]) levels_[2].push_back({static_cast<int>(c), false});
  }
  for (size_t o = 0; o < usable_opening.size(); ++o) {
    if (usable_opening[o]) levels_[2].push_back({static_cast<int>(o), true});
  }
  for (int level = 0; level < 3; ++level) {
    double total = 0, opening_total = 0;
    for (const LeadPart& part : levels_[level]) {
      if (part.opening) {
        opening_total += openings[part.index].weight;
      } else {
        total += component_length[part.index];
      }
    }
    const double share = !(opening_total > 0) ? 0.0 : total > 0 ? options.opening_share : 1.0;
    double sum = 0;
    for (const LeadPart& part : levels_[level]) {
      sum += part.opening ? share * openings[part.index].weight / opening_total
                          : (1 - share) * component_length[part.index] / total;
      cumulative_[level].push_back(sum);
    }
  }
  const std::uint64_t parts = levels_[0].size();
  stage_ = std::max<std::uint64_t>(
      static_cast<std::uint64_t>(std::max(1, options.min_stage_draws)),
      static_cast<std::uint64_t>(std::max(1, options.stage_draws_per_part)) * parts);
}

int LeadLevels::LevelAfter(std::uint64_t draws) const {
  if (draws < stage_) return 0;
  if (draws < 3 * stage_) return 1;
  return 2;
}

const LeadPart* LeadLevels::Pick(int level, double pick_u) const {
  level = std::min(std::max(level, 0), 2);
  const std::vector<LeadPart>& parts = levels_[level];
  if (parts.empty()) return nullptr;
  const std::vector<double>& cumulative = cumulative_[level];
  const double u = std::min(std::max(pick_u, 0.0), 1.0) * cumulative.back();
  const size_t pick = std::min<size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin(),
      parts.size() - 1);
  return &parts[pick];
}

std::vector<int> LeadLevels::ComponentsAt(int level) const {
  std::vector<int> out;
  for (const LeadPart& p : levels_[std::min(std::max(level, 0), 2)]) {
    if (!p.opening) out.push_back(p.index);
  }
  std::sort(out.begin(), out.end());
  return out;
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
    target.across = AcrossAngle(d);
    openings_.push_back(target);
  }

  // The levels and their weights (LeadLevels); degenerate parts (no area, a zero-length
  // opening) are left out.
  std::vector<LeadEdge> edges;
  std::vector<bool> usable_component, usable_opening;
  std::vector<double> size;
  std::vector<Eigen::Vector2d> midpoints;
  for (const ComponentSampler& component : components_) {
    usable_component.push_back(component.area() > 0);
    size.push_back(std::sqrt(component.area()));
  }
  for (size_t o = 0; o < openings_.size(); ++o) {
    edges.push_back({decomposition.openings[o].component_a, decomposition.openings[o].component_b});
    usable_opening.push_back(openings_[o].sigma > 0);
    midpoints.push_back(openings_[o].position);
  }
  levels_ =
      LeadLevels(lead_, edges, usable_component, usable_opening,
                 LengthsAlongLead(lead_, size, query.start, query.goal, midpoints), lead_options);
}

AcdDraw LeadDistribution::Draw(RandomEngine& rng, int level, double pick_u, int* part) const {
  level = std::min(std::max(level, 0), 2);
  const double uniform_share =
      level < 2 ? lead_options_.lead_uniform_share : options_.uniform_share;
  const LeadPart* picked = levels_.Pick(level, pick_u);
  if (!picked || UniformReal(rng, 0.0, 1.0) < uniform_share) return AcdDraw{};
  const LeadPart& chosen = *picked;
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
    draw.yaw = AlignedYaw(rng, target.across, options_);
  }
  if (part) *part = -1 - chosen.index;
  return draw;
}

}  // namespace acdplan::planning::internal
