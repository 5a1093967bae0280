#pragma once
// The geometries without area a polygon reader passed over, and the one note that says so.

#include <map>
#include <string>

namespace acdplan::acd::internal {

/// Counts skipped geometries by type and remembers where the first was.
class SkippedGeometries {
 public:
  /// Counts `count` geometries of `type`; `where` names the place if they are the first.
  void Add(const std::string& type, const std::string& where, int count = 1) {
    if (counts_.empty()) first_ = where;
    counts_[type] += count;
  }
  bool empty() const { return counts_.empty(); }
  /// "<where>: skipped 3 geometries without area (2 LineString, 1 Point; the first at <first>)",
  /// types in alphabetical order.
  std::string Note(const std::string& where) const {
    int total = 0;
    std::string types;
    for (const auto& [type, count] : counts_) {
      total += count;
      types += (types.empty() ? "" : ", ") + std::to_string(count) + " " + type;
    }
    return where + ": skipped " + std::to_string(total) +
           (total == 1 ? " geometry" : " geometries") + " without area (" + types +
           "; the first at " + first_ + ")";
  }

 private:
  std::map<std::string, int> counts_;
  std::string first_;
};

}  // namespace acdplan::acd::internal
