#include "planning/acd_prm.h"

#include <algorithm>

#include "planning/internal/space_access.h"

namespace acdplan::planning {
namespace {

// Even-odd crossing test on one ring.
bool InsideRing(const acd::Ring2d& ring, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const acd::Point2d& a = ring[i];
    const acd::Point2d& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

AcdPrm::AcdPrm(const ompl::base::SpaceInformationPtr& si,
               const acd::Decomposition2d& decomposition, bool star, std::uint64_t seed)
    : PRM(si, star), adjacent_(acd::ComponentGraph(decomposition)), rng_(seed) {
  setName(star ? "PRMstar_ACD" : "PRM_ACD");
  for (const acd::Component2d& component : decomposition.components) {
    components_.push_back(component.polygon);
    Eigen::AlignedBox2d box;
    for (const acd::Point2d& p : component.polygon.outer) box.extend(p);
    boxes_.push_back(box);
  }
  members_.resize(components_.size());
  const internal::SpaceKind kind = internal::Classify(si->getStateSpace().get());
  xy_ = [kind](const ompl::base::State* state) { return internal::Xy(kind, state); };
}

void AcdPrm::setup() {
  PRM::setup();
  if (!nearest_) {
    nearest_ = connectionStrategy_;
    connectionStrategy_ = [this](const Vertex v) -> const std::vector<Vertex>& {
      return Connections(v);
    };
  }
}

void AcdPrm::clear() {
  PRM::clear();
  for (std::vector<Vertex>& members : members_) members.clear();
}

int AcdPrm::Locate(const Eigen::Vector2d& xy) const {
  for (size_t c = 0; c < components_.size(); ++c) {
    if (!boxes_[c].contains(xy) || !InsideRing(components_[c].outer, xy)) continue;
    const auto& holes = components_[c].holes;
    if (std::none_of(holes.begin(), holes.end(),
                     [&xy](const acd::Ring2d& hole) { return InsideRing(hole, xy); })) {
      return static_cast<int>(c);
    }
  }
  return -1;
}

const std::vector<AcdPrm::Vertex>& AcdPrm::Connections(const Vertex v) {
  offered_ = nearest_(v);
  const int home = Locate(xy_(stateProperty_[v]));
  if (home < 0) return offered_;
  // A candidate is worth a motion check only if it would join v to a part of the roadmap not
  // yet offered.
  auto joins_new_part = [this](Vertex u) {
    return std::none_of(offered_.begin(), offered_.end(),
                        [&](Vertex w) { return w == u || sameComponent(w, u); });
  };
  std::vector<int> around = {home};
  around.insert(around.end(), adjacent_[home].begin(), adjacent_[home].end());
  for (int c : around) {
    std::vector<Vertex>& members = members_[c];
    int added = 0;
    // Random picks (with replacement, a bounded number): uniform over the component, where the
    // nearest would again be the milestone's own cluster.
    for (int tries = 0; tries < 4 * kPerComponent && added < kPerComponent && !members.empty();
         ++tries) {
      std::uniform_int_distribution<size_t> pick(0, members.size() - 1);
      const Vertex u = members[pick(rng_)];
      if (joins_new_part(u)) {
        offered_.push_back(u);
        ++added;
      }
    }
  }
  members_[home].push_back(v);
  return offered_;
}

}  // namespace acdplan::planning
