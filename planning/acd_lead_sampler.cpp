#include "planning/acd_lead_sampler.h"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include "base/input_error.h"
#include "planning/internal/lead.h"
#include "planning/internal/space_access.h"

namespace acdplan::planning {

double RobotWidth(const envs::Robot& robot) {
  switch (robot.shape) {
    case envs::RobotShape::kPoint:
    case envs::RobotShape::kMesh:
      return 0.0;
    case envs::RobotShape::kDisc:
      return 2 * robot.radius;
    case envs::RobotShape::kPolygon:
      break;
  }
  // The smallest width is attained with one side of the caliper flush to an edge of the convex
  // hull (rotating calipers): the minimum over the hull's edges of the largest vertex distance.
  std::vector<Eigen::Vector2d> points(robot.polygon.outer.begin(), robot.polygon.outer.end());
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Eigen::Vector2d> hull;  // Andrew's monotone chain, counter-clockwise.
  for (int pass = 0; pass < 2; ++pass) {
    const size_t base = hull.size();
    for (const Eigen::Vector2d& p : points) {
      while (hull.size() >= base + 2 && cross(hull[hull.size() - 2], hull.back(), p) <= 0) {
        hull.pop_back();
      }
      hull.push_back(p);
    }
    hull.pop_back();
    std::reverse(points.begin(), points.end());
  }
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d a = hull[i], d = hull[(i + 1) % hull.size()] - a;
    const double length = d.norm();
    if (!(length > 0)) continue;
    double far = 0;
    for (const Eigen::Vector2d& p : hull) {
      far = std::max(far, std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / length);
    }
    best = std::min(best, far);
  }
  return std::isfinite(best) ? best : 0.0;
}

AcdLeadStateSampler::AcdLeadStateSampler(const ompl::base::StateSpace* space,
                                         std::shared_ptr<const internal::LeadDistribution> lead,
                                         std::uint64_t seed)
    : ompl::base::StateSampler(space),
      lead_(std::move(lead)),
      kind_(internal::Classify(space)),
      rng_engine_(seed),
      phase_(UniformReal(rng_engine_, 0.0, 1.0)) {}

AcdLeadStateSampler::~AcdLeadStateSampler() = default;

int AcdLeadStateSampler::level() const { return lead_->LevelAfter(draws_); }

void AcdLeadStateSampler::sampleUniform(ompl::base::State* state) {
  const int level = lead_->LevelAfter(draws_);
  const double pick = internal::StratifiedPick(phase_, draws_++);
  for (int attempt = 0; attempt < 16; ++attempt) {
    int part = kUniformPart;
    const internal::AcdDraw draw = lead_->Draw(rng_engine_, level, pick, &part);
    if (draw.uniform) break;
    if (internal::SetFromDraw(kind_, space_, draw, state, rng_engine_)) {
      last_part_ = part;
      return;
    }
  }
  last_part_ = kUniformPart;
  internal::SampleUniform(kind_, space_, state, rng_engine_);
}

void AcdLeadStateSampler::sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                                            double distance) {
  internal::SampleUniformNear(kind_, space_, state, near, distance, rng_engine_);
}

void AcdLeadStateSampler::sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                                         double stdDev) {
  internal::SampleGaussian(kind_, space_, state, mean, stdDev, rng_engine_);
}

AcdLeadValidStateSampler::AcdLeadValidStateSampler(
    const ompl::base::SpaceInformation* si, std::shared_ptr<const internal::LeadDistribution> lead,
    std::uint64_t seed, int max_attempts)
    : RejectionValidStateSampler(si, "acd_lead", max_attempts, std::move(lead), seed) {}

void InstallAcdLeadSamplers(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                            const acd::Decomposition2d& decomposition, const AcdLeadQuery& query,
                            const AcdSamplerOptions& options, const AcdLeadOptions& lead_options) {
  if (!(lead_options.narrow_penalty >= 1)) {
    throw InputError("acd_lead: narrow_penalty: expected a number >= 1");
  }
  internal::Classify(si->getStateSpace().get());  // Fail now, not inside the planner.
  auto lead = std::make_shared<const internal::LeadDistribution>(decomposition, query, options,
                                                                 lead_options);
  const std::uint64_t seed = options.seed;
  const int attempts = options.max_attempts;
  auto counter = std::make_shared<std::atomic<std::uint64_t>>(0);
  si->getStateSpace()->setStateSamplerAllocator(
      [lead, seed, counter](const ompl::base::StateSpace* space) {
        return std::make_shared<AcdLeadStateSampler>(space, lead, DeriveSeed(seed, (*counter)++));
      });
  si->setValidStateSamplerAllocator(
      [lead, seed, counter, attempts](const ompl::base::SpaceInformation* info) {
        return std::make_shared<AcdLeadValidStateSampler>(info, lead,
                                                          DeriveSeed(seed, (*counter)++), attempts);
      });
}

}  // namespace acdplan::planning
