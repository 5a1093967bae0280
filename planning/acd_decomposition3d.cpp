#include "planning/acd_decomposition3d.h"

#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <stdexcept>

#include "planning/internal/lead3d.h"

namespace acdplan::planning {

namespace ob = ompl::base;

AcdDecomposition3d::AcdDecomposition3d(const envs::FreeSpaceDecomposition3d& decomposition,
                                       const ob::RealVectorBounds& bounds,
                                       const ob::StateSpace* space)
    : ompl::control::Decomposition(3, bounds), decomposition_(decomposition) {
  if (decomposition_.components.empty()) {
    throw std::invalid_argument("AcdDecomposition3d(): the decomposition has no components");
  }
  if (space->getType() == ob::STATE_SPACE_SE3) {
    se3_ = true;
  } else if (!(space->getType() == ob::STATE_SPACE_REAL_VECTOR && space->getDimension() >= 3)) {
    throw std::invalid_argument("AcdDecomposition3d(): no (x, y, z) in state space '" +
                                space->getName() +
                                "' (expected SE3 or RealVector of dimension >= 3)");
  }
  for (const envs::FreeComponent3d& component : decomposition_.components) {
    Eigen::AlignedBox3d box;
    for (Eigen::Index i = 0; i < component.hull.vertices.rows(); ++i) {
      box.extend(component.hull.vertices.row(i).transpose());
    }
    boxes_.push_back(box);
    samplers_.emplace_back(component);
  }
  neighbors_ = envs::ComponentGraph(decomposition_);
}

AcdDecomposition3d::~AcdDecomposition3d() = default;

int AcdDecomposition3d::getNumRegions() const {
  return static_cast<int>(decomposition_.components.size());
}

double AcdDecomposition3d::getRegionVolume(int rid) {
  return decomposition_.components.at(static_cast<size_t>(rid)).volume;
}

int AcdDecomposition3d::LocatePoint(const Eigen::Vector3d& p) const {
  // As FreeSpaceDecomposition3d::Locate() (the deepest hull), the boxes first.
  int best = -1;
  double best_depth = 0;
  const Eigen::Vector4d h(p.x(), p.y(), p.z(), -1.0);
  for (size_t c = 0; c < boxes_.size(); ++c) {
    if (!boxes_[c].contains(p)) continue;
    const auto& planes = decomposition_.components[c].planes;
    if (planes.rows() == 0) continue;
    const double depth = -(planes * h).maxCoeff();
    if (depth >= 0 && (best < 0 || depth > best_depth)) {
      best = static_cast<int>(c);
      best_depth = depth;
    }
  }
  return best;
}

int AcdDecomposition3d::locateRegion(const ob::State* s) const {
  std::vector<double> coord;
  project(s, coord);
  return LocatePoint(Eigen::Vector3d(coord[0], coord[1], coord[2]));
}

void AcdDecomposition3d::project(const ob::State* s, std::vector<double>& coord) const {
  coord.resize(3);
  if (se3_) {
    const auto* se3 = s->as<ob::SE3StateSpace::StateType>();
    coord[0] = se3->getX(), coord[1] = se3->getY(), coord[2] = se3->getZ();
    return;
  }
  const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
  coord[0] = v[0], coord[1] = v[1], coord[2] = v[2];
}

void AcdDecomposition3d::getNeighbors(int rid, std::vector<int>& neighbors) const {
  neighbors = neighbors_.at(static_cast<size_t>(rid));
}

void AcdDecomposition3d::sampleFromRegion(int rid, ompl::RNG& rng,
                                          std::vector<double>& coord) const {
  const Eigen::Vector3d p =
      samplers_.at(static_cast<size_t>(rid)).Sample([&rng] { return rng.uniform01(); });
  coord.assign({p.x(), p.y(), p.z()});
}

void AcdDecomposition3d::sampleFullState(const ob::StateSamplerPtr& sampler,
                                         const std::vector<double>& coord, ob::State* s) const {
  sampler->sampleUniform(s);
  if (se3_) {
    s->as<ob::SE3StateSpace::StateType>()->setXYZ(coord[0], coord[1], coord[2]);
    return;
  }
  double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
  v[0] = coord[0], v[1] = coord[1], v[2] = coord[2];
}

}  // namespace acdplan::planning
