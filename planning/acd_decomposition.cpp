#include "planning/acd_decomposition.h"

#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <cmath>
#include <stdexcept>

#include "acd/component_locator2d.h"
#include "planning/internal/component_sampler.h"

namespace acdplan::planning {

namespace ob = ompl::base;

AcdDecomposition::AcdDecomposition(const acd::Decomposition2d& decomposition,
                                   const ob::RealVectorBounds& bounds, const ob::StateSpace* space)
    : ompl::control::Decomposition(2, bounds), decomposition_(decomposition) {
  if (decomposition_.components.empty()) {
    throw std::invalid_argument("AcdDecomposition(): the decomposition has no components");
  }
  if (space->getType() == ob::STATE_SPACE_SE2) {
    access_ = Access::kSE2;
  } else if (space->getType() == ob::STATE_SPACE_REAL_VECTOR && space->getDimension() >= 2) {
    access_ = Access::kRealVector;
  } else if (space->isCompound() && space->as<ob::CompoundStateSpace>()->getSubspaceCount() > 0 &&
             space->as<ob::CompoundStateSpace>()->getSubspace(0)->getType() ==
                 ob::STATE_SPACE_SE2) {
    access_ = Access::kCompoundSE2;
  } else {
    throw std::invalid_argument("AcdDecomposition(): no (x, y) in state space '" +
                                space->getName() +
                                "' (expected RealVector of dimension >= 2, SE2, or a compound "
                                "space whose first subspace is SE2)");
  }
  locator_ = std::make_unique<acd::ComponentLocator2d>(decomposition_);
  for (const acd::Component2d& component : decomposition_.components) {
    samplers_.emplace_back(component);
    areas_.push_back(samplers_.back().area());
  }
  neighbors_ = acd::ComponentGraph(decomposition_);
}

AcdDecomposition::~AcdDecomposition() = default;

int AcdDecomposition::getNumRegions() const {
  return static_cast<int>(decomposition_.components.size());
}

double AcdDecomposition::getRegionVolume(int rid) { return areas_.at(static_cast<size_t>(rid)); }

int AcdDecomposition::LocatePoint(const Eigen::Vector2d& p) const { return locator_->Locate(p); }

int AcdDecomposition::locateRegion(const ob::State* s) const {
  std::vector<double> coord;
  project(s, coord);
  return LocatePoint(Eigen::Vector2d(coord[0], coord[1]));
}

void AcdDecomposition::project(const ob::State* s, std::vector<double>& coord) const {
  coord.resize(2);
  switch (access_) {
    case Access::kRealVector: {
      const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
      coord[0] = v[0], coord[1] = v[1];
      return;
    }
    case Access::kSE2: {
      const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
      coord[0] = se2->getX(), coord[1] = se2->getY();
      return;
    }
    case Access::kCompoundSE2: {
      const auto* se2 =
          s->as<ob::CompoundStateSpace::StateType>()->as<ob::SE2StateSpace::StateType>(0);
      coord[0] = se2->getX(), coord[1] = se2->getY();
      return;
    }
  }
}

void AcdDecomposition::getNeighbors(int rid, std::vector<int>& neighbors) const {
  neighbors = neighbors_.at(static_cast<size_t>(rid));
}

void AcdDecomposition::sampleFromRegion(int rid, ompl::RNG& rng, std::vector<double>& coord) const {
  const Eigen::Vector2d p =
      samplers_.at(static_cast<size_t>(rid)).Sample([&rng] { return rng.uniform01(); });
  coord.assign({p.x(), p.y()});
}

void AcdDecomposition::sampleFullState(const ob::StateSamplerPtr& sampler,
                                       const std::vector<double>& coord, ob::State* s) const {
  sampler->sampleUniform(s);
  switch (access_) {
    case Access::kRealVector: {
      double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
      v[0] = coord[0], v[1] = coord[1];
      return;
    }
    case Access::kSE2:
      s->as<ob::SE2StateSpace::StateType>()->setXY(coord[0], coord[1]);
      return;
    case Access::kCompoundSE2:
      s->as<ob::CompoundStateSpace::StateType>()->as<ob::SE2StateSpace::StateType>(0)->setXY(
          coord[0], coord[1]);
      return;
  }
}

}  // namespace acdplan::planning
