#include "collision/collision_mode.h"

#include "base/enum_names.h"

namespace acdplan::collision {
namespace {

constexpr std::array<EnumName<CollisionMode>, 3> kModes = {{
    {CollisionMode::kBvh, "bvh"},
    {CollisionMode::kHulls, "hulls"},
    {CollisionMode::kHullsExact, "hulls+exact"},
}};

}  // namespace

std::string ToString(CollisionMode mode) { return NameOf(kModes, mode); }

CollisionMode ParseCollisionMode(const std::string& name) {
  return ValueOf(kModes, name, "collision mode");
}

std::vector<CollisionMode> AllCollisionModes() {
  std::vector<CollisionMode> modes;
  for (const auto& entry : kModes) modes.push_back(entry.value);
  return modes;
}

}  // namespace acdplan::collision
