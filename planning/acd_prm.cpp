#include "planning/acd_prm.h"

#include <algorithm>
#include <stdexcept>

#include "planning/internal/space_access.h"
#include "planning/internal/space_access3d.h"

namespace acdplan::planning {

AcdPrm::AcdPrm(const ompl::base::SpaceInformationPtr& si, const acd::Decomposition2d& decomposition,
               bool star, std::uint64_t seed)
    : PRM(si, star),
      locator_(decomposition),
      adjacent_(acd::ComponentGraph(decomposition)),
      rng_(seed) {
  setName(star ? "PRMstar_ACD" : "PRM_ACD");
  members_.resize(decomposition.components.size());
  const internal::SpaceKind kind = internal::Classify(si->getStateSpace().get());
  xy_ = [kind](const ompl::base::State* state) { return internal::Xy(kind, state); };
  locate_state_ = [this](const ompl::base::State* state) { return Locate(xy_(state)); };
}

AcdPrm::AcdPrm(const ompl::base::SpaceInformationPtr& si,
               std::shared_ptr<const envs::FreeSpaceDecomposition3d> decomposition, bool star,
               std::uint64_t seed)
    : PRM(si, star),
      locator_(acd::Decomposition2d{}),
      adjacent_(envs::ComponentGraph(*decomposition)),
      rng_(seed),
      decomposition3d_(std::move(decomposition)) {
  setName(star ? "PRMstar_ACD" : "PRM_ACD");
  members_.resize(decomposition3d_->components.size());
  const internal::SpaceKind kind = internal::Classify(si->getStateSpace().get());
  if (kind != internal::SpaceKind::kRealVector3 && kind != internal::SpaceKind::kSE3) {
    throw std::invalid_argument("AcdPrm: a 3D decomposition needs RealVector(3) or SE3, not '" +
                                si->getStateSpace()->getName() + "'");
  }
  const envs::FreeSpaceDecomposition3d* d = decomposition3d_.get();
  locate_state_ = [kind, d](const ompl::base::State* state) {
    return d->Locate(internal::Position3d(kind, state));
  };
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

int AcdPrm::Locate(const Eigen::Vector2d& xy) const { return locator_.Locate(xy); }

const std::vector<AcdPrm::Vertex>& AcdPrm::Connections(const Vertex v) {
  offered_ = nearest_(v);
  const int home = locate_state_(stateProperty_[v]);
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
      const Vertex u = members[UniformIndex(rng_, members.size())];
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
