#include "planning/counting_validity_checker.h"

#include <utility>

namespace acdplan::planning {

CountingValidityChecker::CountingValidityChecker(ompl::base::SpaceInformation* si, Predicate valid)
    : ompl::base::StateValidityChecker(si), valid_(std::move(valid)) {}

bool CountingValidityChecker::isValid(const ompl::base::State* state) const {
  ++checks_;
  return valid_(state);
}

}  // namespace acdplan::planning
