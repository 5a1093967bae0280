#include "collision/collision_mode.h"

#include "acd/input_error.h"

namespace acdplan::collision {

std::string ModeName(CollisionMode mode) {
  switch (mode) {
    case CollisionMode::kBvh:
      return "bvh";
    case CollisionMode::kHulls:
      return "hulls";
    case CollisionMode::kHullsExact:
      return "hulls+exact";
  }
  return "unknown";
}

CollisionMode ParseCollisionMode(const std::string& name) {
  for (CollisionMode mode : AllCollisionModes()) {
    if (ModeName(mode) == name) return mode;
  }
  throw acd::InputError("ParseCollisionMode(): unknown collision mode '" + name +
                        "'; expected bvh, hulls or hulls+exact");
}

std::vector<CollisionMode> AllCollisionModes() {
  return {CollisionMode::kBvh, CollisionMode::kHulls, CollisionMode::kHullsExact};
}

}  // namespace acdplan::collision
