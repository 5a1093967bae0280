#include "collision/point_locator.h"

#include <optional>

#include "base/enum_names.h"
#include "collision/internal/hull_grid.h"
#include "collision/internal/solid_locator.h"

namespace acdplan::collision {

namespace {

constexpr std::array<EnumName<LocateMethod>, 2> kMethods = {{
    {LocateMethod::kExact, "exact"},
    {LocateMethod::kHulls, "hulls"},
}};

}  // namespace

std::string ToString(LocateMethod method) { return NameOf(kMethods, method); }

LocateMethod ParseLocateMethod(const std::string& name) {
  return ValueOf(kMethods, name, "locate method");
}

struct PointLocator::Impl {
  std::optional<internal::ExactObstacleLocator> exact;
  internal::HullGrid hulls;
};

PointLocator::PointLocator(std::shared_ptr<const ObstacleSet> obstacles, LocateMethod method)
    : obstacles_(std::move(obstacles)), method_(method), impl_(std::make_unique<Impl>()) {
  if (method_ == LocateMethod::kExact) {
    impl_->exact.emplace(*obstacles_, /*skip_open=*/false);
  } else {
    std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>> planes;
    std::vector<Eigen::AlignedBox3d> boxes;
    for (const ObstaclePiece& piece : obstacles_->pieces) {
      planes.push_back(piece.planes);
      boxes.push_back(piece.box);
    }
    // Slack: a few ulps of the world's size, so a point of a component on its hull's boundary
    // is never rounded outside the hull (the hull test must stay conservative).
    const double slack = 1e-12 * (1 + obstacles_->bounds.sizes().norm() +
                                  obstacles_->bounds.max().cwiseAbs().maxCoeff() +
                                  obstacles_->bounds.min().cwiseAbs().maxCoeff());
    impl_->hulls = internal::HullGrid(planes, boxes, slack, obstacles_->dimension == 2,
                                      internal::HullGrid::kFineCells);
  }
}

PointLocator::~PointLocator() = default;
PointLocator::PointLocator(PointLocator&&) noexcept = default;
PointLocator& PointLocator::operator=(PointLocator&&) noexcept = default;

bool PointLocator::Inside(const Eigen::Vector3d& p) const {
  if (method_ == LocateMethod::kExact) return impl_->exact->Inside(p);
  return impl_->hulls.AnyContains(p);
}

void PointLocator::Inside(const std::vector<Eigen::Vector3d>& points,
                          std::vector<char>* inside) const {
  inside->resize(points.size());
  char* out = inside->data();
  if (method_ == LocateMethod::kExact) {
    for (size_t i = 0; i < points.size(); ++i) out[i] = impl_->exact->Inside(points[i]);
    return;
  }
  const internal::HullGrid& grid = impl_->hulls;
  for (size_t i = 0; i < points.size(); ++i) out[i] = grid.AnyContains(points[i]);
}

}  // namespace acdplan::collision
