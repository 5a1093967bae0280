#pragma once
// The one exception type for bad user input, shared by every module; the command line maps it
// to exit status 2.

#include <stdexcept>
#include <string>
#include <vector>

namespace acdplan {

/// Thrown when input breaks a documented rule. what() is one line that names the file (or
/// element), the line or key path where known, and the rule broken, e.g.
/// "bird.poly:47: malformed number '-6.64248.788605'" or
/// "demo.yaml: planner.time_limit: expected a positive number, got 'fast'".
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// "a, b, c": the names of a list as messages show them.
std::string JoinNames(const std::vector<std::string>& names);

/// "unknown <what> '<name>' (expected one of: a, b, c)": the one wording for a name that is
/// not one of `known`, whether a key, a planner or a generator.
std::string UnknownName(const std::string& what, const std::string& name,
                        const std::vector<std::string>& known);

}  // namespace acdplan
