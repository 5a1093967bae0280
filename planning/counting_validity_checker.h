#pragma once
// A state validity checker that counts its calls (the "collision checks" of every report).

#include <ompl/base/StateValidityChecker.h>

#include <atomic>
#include <cstdint>
#include <functional>

namespace acdplan::planning {

/// Wraps a validity predicate and counts how often it is asked (thread-safe counter).
/// The predicate must be safe to call from several threads if the planner is multi-threaded.
class CountingValidityChecker : public ompl::base::StateValidityChecker {
 public:
  using Predicate = std::function<bool(const ompl::base::State*)>;

  CountingValidityChecker(ompl::base::SpaceInformation* si, Predicate valid);

  bool isValid(const ompl::base::State* state) const override;

  /// Calls of isValid() since construction or the last ResetChecks().
  std::uint64_t checks() const { return checks_.load(); }
  void ResetChecks() { checks_ = 0; }

 private:
  Predicate valid_;
  mutable std::atomic<std::uint64_t> checks_{0};
};

}  // namespace acdplan::planning
