#include "envs/workspace2d.h"

#include <cmath>
#include <sstream>

#include "acd/prepare_polygon.h"
#include "base/input_error.h"

namespace acdplan::envs {

acd::Polygon2d BoundsPolygon(const Eigen::AlignedBox2d& bounds) {
  const Eigen::Vector2d lo = bounds.min(), hi = bounds.max();
  return acd::Polygon2d{{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, {}};
}

Workspace2d PrepareWorkspace2d(const Workspace2d& raw, const std::string& where) {
  const Eigen::Vector2d lo = raw.bounds.min(), hi = raw.bounds.max();
  if (!lo.allFinite() || !hi.allFinite() || !(lo.x() < hi.x()) || !(lo.y() < hi.y())) {
    std::ostringstream message;
    message << where << ": bounds: expected finite xmin < xmax and ymin < ymax, got [" << lo.x()
            << ", " << lo.y() << ", " << hi.x() << ", " << hi.y() << "]";
    throw InputError(message.str());
  }
  Workspace2d result;
  result.bounds = raw.bounds;
  result.description = raw.description;
  result.obstacles.reserve(raw.obstacles.size());
  for (size_t k = 0; k < raw.obstacles.size(); ++k) {
    result.obstacles.push_back(
        acd::PreparePolygon(raw.obstacles[k], where + ": obstacle " + std::to_string(k)));
  }
  return result;
}

}  // namespace acdplan::envs
